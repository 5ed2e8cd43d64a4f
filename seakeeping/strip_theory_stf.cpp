#include "seakeeping/strip_theory_stf.h"

#include <cmath>
#include <stdexcept>

#include "seakeeping/encounter_frequency.h"
#include "seakeeping/periodic_motion_solver.h"

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

RaoTable SolveStripTheoryRaos(const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s,
                              const SectionRowProvider& rows) {
  if (omega_rad_s.empty()) throw std::invalid_argument("RAO sweep: the frequency list is empty");
  const int N = model.Steps();
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
    const double w = omega_rad_s[f];
    if (!(w > 0.0) || !std::isfinite(w))
      throw std::invalid_argument("RAO sweep: wave frequency " + std::to_string(w) + " rad/s must be > 0");
    const double we = HeadSeaEncounterFrequency(w, model.speed(), model.g());
    std::vector<Eigen::RowVectorXcd> r(N);
    for (int n = 0; n < N; ++n) {
      r[n] = rows(n, we);
      if (r[n].size() != model.stations()[n].nz.size())
        throw std::invalid_argument("strip theory: section row size differs from the panel count at step " +
                                    std::to_string(n));
    }
    const std::complex<double> scale = 1.0 / std::complex<double>(0.0, we * model.dt());  // 1/(iω_e Δt)
    PeriodicStripForce strip;
    strip.first_step = [](int n) { return n > 0 ? n - 1 : 0; };
    strip.dot = [&r, scale](int n, int m, const Eigen::VectorXd& v, double) -> std::complex<double> {
      const std::complex<double> d = r[m] * v.cast<std::complex<double>>();
      return m == n ? scale * d : -scale * d;
    };
    const auto x = SolvePeriodicFrequency(model, w, strip);
    out.omega_e_rad_s[f] = we;
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
