#include "seakeeping/motions/strip_theory_stf.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "seakeeping/motions/encounter_frequency.h"
#include "seakeeping/sections/frequency_domain_section.h"
#include "seakeeping/motions/periodic_motion_solver.h"

namespace hullopt::sk {

Eigen::RowVectorXcd UniformHeaveRow(const std::vector<Panel>& panels, double a33, double b33,
                                    double omega_e) {
  const auto n = static_cast<Eigen::Index>(panels.size());
  Eigen::RowVectorXcd r(n);
  double norm = 0.0;
  for (const auto& p : panels) norm += std::pow(p.Normal()[1], 2) * p.Length();
  const std::complex<double> z(-b33, -omega_e * a33);  // −(iω_e a33 + b33)
  for (Eigen::Index i = 0; i < n; ++i)
    r[i] = norm > 0 ? z * panels[i].Normal()[1] * panels[i].Length() / norm : 0.0;
  return r;
}

SectionRowProvider FrequencyDomainSectionRows(const StripKernel& geometry, int panels_per_body,
                                              bool interaction, SectionFormulation formulation) {
  if (panels_per_body < 1)
    throw std::invalid_argument("FrequencyDomainSectionRows: panels_per_body must be >= 1");
  // Per step: the section solvers (one strip with every body, or one per body), prepared once on first use
  // (panels, lid, Rankine parts) and shared by all frequencies; and the rows already computed.
  struct Step {
    std::once_flag once;
    std::vector<SectionHeaveSolver> solvers;
    // Per body (one entry with interaction): its solver, and whether the body is the mirror image about
    // y = 0 of that solver's body (its potentials then read in reverse panel order).
    std::vector<std::pair<std::size_t, bool>> bodies;
  };
  struct Cache {
    std::mutex mutex;
    std::map<std::pair<int, double>, Eigen::RowVectorXcd> rows;
    std::vector<std::unique_ptr<Step>> steps;
  };
  auto cache = std::make_shared<Cache>();
  for (std::size_t n = 0; n < geometry.panels.size(); ++n) cache->steps.push_back(std::make_unique<Step>());
  const StripKernel* g = &geometry;
  return [cache, g, panels_per_body, interaction, formulation](int n, double omega_e) -> Eigen::RowVectorXcd {
    {
      std::lock_guard<std::mutex> lock(cache->mutex);
      const auto it = cache->rows.find({n, omega_e});
      if (it != cache->rows.end()) return it->second;
    }
    const auto& all = g->panels.at(n);
    Eigen::RowVectorXcd r = Eigen::RowVectorXcd::Zero(static_cast<Eigen::Index>(all.size()));
    if (!all.empty()) {
      if (all.size() % panels_per_body != 0)
        throw std::invalid_argument(
            "FrequencyDomainSectionRows: panel count is not a multiple of panels_per_body");
      Step& step = *cache->steps[n];
      std::call_once(step.once, [&] {
        std::vector<std::vector<Panel>> sections;
        for (std::size_t i = 0; i < all.size(); i += panels_per_body)
          sections.emplace_back(all.begin() + i, all.begin() + i + panels_per_body);
        FrequencyDomainOptions o;
        o.rho_kg_m3 = g->rho_kg_m3;
        o.g_m_s2 = g->g_m_s2;
        o.formulation = formulation;
        if (interaction) {
          step.solvers.emplace_back(sections, o);
          step.bodies.emplace_back(0, false);
          return;
        }
        // Each body alone: a body that is the mirror image about y = 0 of one already prepared (the two
        // demihulls of a catamaran) shares its solver.
        double size = 0.0;
        for (const Panel& p : all) size = std::max({size, std::fabs(p.y1), std::fabs(p.z1)});
        std::vector<std::size_t> solver_of(sections.size());
        for (std::size_t b = 0; b < sections.size(); ++b) {
          const std::size_t partner = sections.size() - 1 - b;
          if (partner < b && MirrorImagePanels(sections[b], sections[partner], 0.0, 1e-12 * size)) {
            step.bodies.emplace_back(solver_of[partner], true);
            continue;
          }
          solver_of[b] = step.solvers.size();
          step.solvers.emplace_back(std::vector<std::vector<Panel>>{sections[b]}, o);
          step.bodies.emplace_back(solver_of[b], false);
        }
      });
      // F3 = iω_e ρ ∮ φ n_z dl (p = −iω_e ρ φ, n into the fluid); by reciprocity the heave force of a normal
      // velocity V is iω_e ρ ∮ ψ_heave V dl.
      const std::complex<double> c(0.0, omega_e * g->rho_kg_m3);
      std::vector<Eigen::VectorXcd> psi;
      for (const SectionHeaveSolver& solver : step.solvers) psi.push_back(solver.HeavePotential(omega_e));
      Eigen::Index i = 0;
      for (const auto& [solver, mirrored] : step.bodies) {
        const Eigen::VectorXcd& p = psi[solver];
        for (Eigen::Index k = 0; k < p.size(); ++k, ++i)
          r[i] = c * (mirrored ? p[p.size() - 1 - k] : p[k]) * all[i].Length();
      }
    }
    std::lock_guard<std::mutex> lock(cache->mutex);
    cache->rows[{n, omega_e}] = r;
    return r;
  };
}

std::vector<HeadSeaCoefficients> StripTheoryCoefficients(const HeadSeaShipModel& model,
                                                         const std::vector<double>& omega_rad_s,
                                                         const SectionRowProvider& rows) {
  if (omega_rad_s.empty()) throw std::invalid_argument("RAO sweep: the frequency list is empty");
  const int N = model.Steps();
  const int nf = static_cast<int>(omega_rad_s.size());
  std::vector<double> encounter(nf);
  for (int i = 0; i < nf; ++i) {
    const double w = omega_rad_s[i];
    if (!(w > 0.0) || !std::isfinite(w))
      throw std::invalid_argument("RAO sweep: wave frequency " + std::to_string(w) + " rad/s must be > 0");
    encounter[i] = HeadSeaEncounterFrequency(w, model.speed(), model.g());
  }
  // Every (frequency, station) section problem is independent: all of them in one parallel loop (each row
  // computed by one thread, so the rows are the same for any thread count), then the serial assembly.
  std::vector<std::vector<Eigen::RowVectorXcd>> all_rows(nf, std::vector<Eigen::RowVectorXcd>(N));
  std::exception_ptr failure = nullptr;
#pragma omp parallel for schedule(dynamic, 1)
  for (int job = 0; job < nf * N; ++job) {
    try {
      all_rows[job / N][job % N] = rows(job % N, encounter[job / N]);
    } catch (...) {
#pragma omp critical(strip_theory_rows)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  std::vector<HeadSeaCoefficients> out;
  for (int i = 0; i < nf; ++i) {
    const double w = omega_rad_s[i], we = encounter[i];
    const std::vector<Eigen::RowVectorXcd>& r = all_rows[i];
    for (int n = 0; n < N; ++n)
      if (r[n].size() != model.stations()[n].nz.size())
        throw std::invalid_argument("strip theory: section row size differs from the panel count at step " +
                                    std::to_string(n));
    // f = (iω_e − U∂x)[F/(iω_e)] = F − (U/iω_e) ∂x F with F = R·Ṽ the 2D force of the section at x_n, the
    // x-derivative a backward difference along the strip (step n − 1 lies Δx forward):
    //   f_n = F_n + (F_n − F_{n−1})/(iω_e Δt).
    // The difference rows of the half-weight end faces (kCellFaces) are doubled so that the hull sum
    // telescopes to the transom term (U/iω_e) F_T exactly. PeriodicCoefficients multiplies the row of step
    // n − 1 by the strip lag e^{−iω_e Δt}; strip theory has no strip history, so the row carries e^{+iω_e Δt}
    // to cancel it. (Applying the lag instead, (F_n − e^{−iω_e Δt} F_{n−1})/(iω_e Δt), is a first-order
    // time difference whose phase error ω_e Δt/2 mixes a33 into b33: b' ≈ b + ω_e Δt ω_e a/2, about +11% on
    // B33 at the Delft heave resonance with 40 sections at Fn 0.75.)
    const double theta = we * model.dt();
    const std::complex<double> scale = 1.0 / std::complex<double>(0.0, theta);  // 1/(iω_e Δt)
    const std::complex<double> unlag = std::polar(1.0, theta);
    PeriodicStripForce strip;
    strip.first_step = [](int n) { return n > 0 ? n - 1 : 0; };
    const auto& st = model.stations();
    const double dx = model.dx();
    strip.dot = [&r, &st, dx, scale, unlag](int n, int m, const Eigen::VectorXd& v,
                                            double) -> std::complex<double> {
      const std::complex<double> d = r[m] * v.cast<std::complex<double>>();
      const std::complex<double> s = st[n].weight_m == dx ? scale : scale * (dx / st[n].weight_m);
      return m == n ? (1.0 + s) * d : -s * unlag * d;
    };
    out.push_back(PeriodicCoefficients(model, w, strip));
  }
  return out;
}

RaoTable SolveStripTheoryRaos(const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s,
                              const SectionRowProvider& rows) {
  const std::vector<HeadSeaCoefficients> c = StripTheoryCoefficients(model, omega_rad_s, rows);
  const auto nf = static_cast<int>(omega_rad_s.size());
  RaoTable out;
  out.speed_m_s = model.speed();
  out.g_m_s2 = model.g();
  out.omega_rad_s = omega_rad_s;
  out.omega_e_rad_s.resize(nf);
  out.heave.resize(nf);
  out.pitch.resize(nf);
  std::vector<int> bad(nf, 0);
  for (int f = 0; f < nf; ++f) {
    const auto x = c[f].Solve();
    out.omega_e_rad_s[f] = c[f].omega_e_rad_s;
    out.heave[f] = x[0];
    out.pitch[f] = x[1];
    bad[f] = !(std::isfinite(x[0].real()) && std::isfinite(x[0].imag()) && std::isfinite(x[1].real()) &&
               std::isfinite(x[1].imag()));
  }
  for (int f = 0; f < nf; ++f)
    if (bad[f]) model.ReportNonFinite("heave/pitch RAO (strip theory)", omega_rad_s[f]);
  return out;
}

}  // namespace hullopt::sk
