#include "evaluation/adaptive_frequency_grid.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "optimizer/evaluation_cost.h"

namespace hullopt::eval {
namespace {

// An interval shorter than this fraction of the grid's range is not halved again: far below any physical
// peak width (a Cs-0 resonance that keeps narrowing is left to the caps and the resonance warning).
constexpr double kMinIntervalFraction = 1e-6;

// The measures whose change between passes decides (b): MSI and rms acceleration per sea and position.
struct Measures {
  std::vector<double> msi_pct, rms_g;
};

Measures Measure(const sk::RaoTable& t, const GridSeas* seas) {
  Measures m;
  if (!seas || seas->spectra.empty()) return m;
  const sk::DesignEvaluation ev = sk::EvaluateDesign(t, seas->hull, seas->spectra, seas->points, seas->options);
  for (const auto& s : ev.seas)
    for (const auto& p : s.positions) {
      m.msi_pct.push_back(p.msi_pct);
      m.rms_g.push_back(p.rms_accel_g);
    }
  return m;
}

// Largest change of the MSI [points] and of the rms acceleration [relative] between two passes.
void Changes(const Measures& a, const Measures& b, double* msi, double* rms) {
  *msi = *rms = 0.0;
  for (std::size_t i = 0; i < a.msi_pct.size() && i < b.msi_pct.size(); ++i) {
    *msi = std::max(*msi, std::abs(a.msi_pct[i] - b.msi_pct[i]));
    const double scale = std::max(std::abs(a.rms_g[i]), std::abs(b.rms_g[i]));
    if (scale > 0) *rms = std::max(*rms, std::abs(a.rms_g[i] - b.rms_g[i]) / scale);
  }
}

const std::vector<std::complex<double>>& Quantity(const sk::RaoTable& t, int q) { return q == 0 ? t.heave : t.pitch; }

// Frequencies around the peaks to refine: the midpoints beside the largest sample and the fitted peak.
// previous: the fitted peaks of the last pass (NaN: none); changed: the largest relative change, out.
void PeakInsertions(const sk::RaoTable& t, const double previous[2], double tolerance, std::vector<double>* out,
                    double* changed) {
  *changed = 0.0;
  for (int q = 0; q < 2; ++q) {
    const sk::RaoPeakFit f = sk::FitRaoPeak(t.omega_rad_s, Quantity(t, q));
    if (!f.fitted_ok) continue;
    const double change = std::isfinite(previous[q]) ? std::abs(f.fitted - previous[q]) / previous[q] : 0.0;
    if (std::isfinite(change)) *changed = std::max(*changed, change);
    if (!f.UnderSampled(tolerance) && std::isfinite(f.fitted) && change <= tolerance) continue;
    const double* w = &t.omega_rad_s[f.at - 1];
    out->push_back(0.5 * (w[0] + w[1]));
    out->push_back(0.5 * (w[1] + w[2]));
    out->push_back(f.omega_fitted);
  }
}

// Midpoints of the intervals where the trapezoid and the parabola through the interval and a neighbour
// disagree most, for each sea and position, until the disagreement left is below `tolerance` of the integral.
void IntegrandInsertions(const sk::RaoTable& t, const GridSeas* seas, double tolerance, std::vector<double>* out) {
  if (!seas || seas->spectra.empty()) return;
  std::vector<double> x;
  for (const auto& p : sk::StandardPassengerPositions(seas->hull.cg_to_transom_m)) x.push_back(p.x_from_cg_m);
  for (const auto& p : seas->points) x.push_back(p.x_from_cg_m);
  const auto& w = t.omega_rad_s;
  const std::size_t n = w.size();
  std::vector<double> f(n), err(n - 1);
  std::vector<std::size_t> order(n - 1);
  for (const auto& s : seas->spectra)
    for (double xp : x) {
      for (std::size_t i = 0; i < n; ++i) {
        const double k = w[i] * w[i] / t.g_m_s2, we2 = t.omega_e_rad_s[i] * t.omega_e_rad_s[i];
        f[i] = s.Density(w[i]) * we2 * we2 * std::norm(t.heave[i] - xp * k * t.pitch[i]);
      }
      double integral = 0.0;
      for (std::size_t i = 0; i + 1 < n; ++i) {
        const double h = w[i + 1] - w[i], trapezoid_mid = 0.5 * (f[i] + f[i + 1]);
        integral += h * trapezoid_mid;
        // Parabola through three samples (Newton form from the first), at the interval's midpoint: the
        // interval's Simpson integral minus its trapezoid is (2/3) h (p(mid) − mean of the ends).
        auto parabola_mid = [&](std::size_t j) {
          const double a1 = (f[j + 1] - f[j]) / (w[j + 1] - w[j]);
          const double a2 = ((f[j + 2] - f[j + 1]) / (w[j + 2] - w[j + 1]) - a1) / (w[j + 2] - w[j]);
          const double m = 0.5 * (w[i] + w[i + 1]);
          return f[j] + a1 * (m - w[j]) + a2 * (m - w[j]) * (m - w[j + 1]);
        };
        double e = 0.0;
        if (i >= 1) e = std::max(e, std::abs(parabola_mid(i - 1) - trapezoid_mid));
        if (i + 2 < n) e = std::max(e, std::abs(parabola_mid(i) - trapezoid_mid));
        err[i] = 2.0 / 3.0 * h * e;
      }
      if (!(integral > 0.0)) continue;
      double left = 0.0;
      for (double e : err) left += e;
      for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
      std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return err[a] > err[b]; });
      for (std::size_t i : order) {
        if (left <= tolerance * integral) break;
        out->push_back(0.5 * (w[i] + w[i + 1]));
        left -= err[i];
      }
    }
}

// The candidates not already in the grid (nor closer than the shortest interval allowed to a sample), in the
// order given (earlier ones first when the frequency cap truncates), at most `budget`.
std::vector<double> NewFrequencies(const std::vector<double>& grid, const std::vector<double>& candidates,
                                   std::size_t budget) {
  const double min_gap = kMinIntervalFraction * (grid.back() - grid.front());
  std::vector<double> taken;
  for (double c : candidates) {
    if (taken.size() >= budget) break;
    if (!(c > grid.front() && c < grid.back())) continue;
    const auto it = std::lower_bound(grid.begin(), grid.end(), c);
    if (*it - c < min_gap || c - *(it - 1) < min_gap) continue;
    bool dup = false;
    for (double u : taken) dup = dup || std::abs(u - c) < min_gap;
    if (!dup) taken.push_back(c);
  }
  std::sort(taken.begin(), taken.end());
  return taken;
}

}  // namespace

bool AdaptiveGridOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  const std::pair<const char*, double> tolerances[] = {{"peak_tolerance", peak_tolerance},
                                                       {"msi_tolerance_pct", msi_tolerance_pct},
                                                       {"rms_tolerance", rms_tolerance},
                                                       {"integrand_tolerance", integrand_tolerance}};
  for (const auto& [name, v] : tolerances)
    if (!(v > 0.0) || !std::isfinite(v)) return fail(std::string(name) + " = " + std::to_string(v) + ": must be > 0");
  if (max_passes < 1 || max_passes > 50)
    return fail("max_passes = " + std::to_string(max_passes) + ": must lie in [1, 50]");
  if (max_frequencies < 3 || max_frequencies > 10000)
    return fail("max_frequencies = " + std::to_string(max_frequencies) + ": must lie in [3, 10000]");
  return true;
}

sk::RaoTable MergeRaoTables(const sk::RaoTable& a, const sk::RaoTable& b) {
  sk::RaoTable m;
  m.speed_m_s = a.speed_m_s;
  m.g_m_s2 = a.g_m_s2;
  m.warnings = a.warnings;
  std::size_t i = 0, j = 0;
  while (i < a.omega_rad_s.size() || j < b.omega_rad_s.size()) {
    const bool from_a = j >= b.omega_rad_s.size() || (i < a.omega_rad_s.size() && a.omega_rad_s[i] < b.omega_rad_s[j]);
    const sk::RaoTable& s = from_a ? a : b;
    const std::size_t k = from_a ? i++ : j++;
    m.omega_rad_s.push_back(s.omega_rad_s[k]);
    m.omega_e_rad_s.push_back(s.omega_e_rad_s[k]);
    m.heave.push_back(s.heave[k]);
    m.pitch.push_back(s.pitch[k]);
  }
  return m;
}

AdaptiveGridResult RefineFrequencyGrid(const std::vector<double>& omega_rad_s, const RaoSolve& solve,
                                       const AdaptiveGridOptions& o, const GridSeas* seas) {
  AdaptiveGridResult r;
  r.start_count = omega_rad_s.size();
  std::string error;
  if (o.enabled && !o.IsValid(&error)) throw std::invalid_argument("adaptive frequency grid: " + error);
  r.rao = solve(omega_rad_s);
  if (!o.enabled || omega_rad_s.size() < 3) return r;
  Measures measures = Measure(r.rao, seas);
  double fitted[2] = {NAN, NAN};
  double peak_change = 0.0, msi_change = 0.0, rms_change = 0.0;
  const char* stopped_by = nullptr;
  for (int pass = 1;; ++pass) {
    std::vector<double> candidates;
    PeakInsertions(r.rao, fitted, o.peak_tolerance, &candidates, &peak_change);
    const bool peaks_resolved = candidates.empty();
    if (pass > 1 && peaks_resolved && msi_change < o.msi_tolerance_pct && rms_change < o.rms_tolerance) break;
    IntegrandInsertions(r.rao, seas, o.integrand_tolerance, &candidates);
    const std::size_t room =
        r.rao.omega_rad_s.size() < static_cast<std::size_t>(o.max_frequencies) ? o.max_frequencies - r.rao.omega_rad_s.size() : 0;
    const std::vector<double> added = NewFrequencies(r.rao.omega_rad_s, candidates, room);
    if (added.empty() && (room > 0 || candidates.empty())) break;  // nothing left to refine
    if (added.empty() || pass > o.max_passes) {
      stopped_by = added.empty() ? "frequencies" : "passes";
      break;
    }
    for (int q = 0; q < 2; ++q) fitted[q] = sk::FitRaoPeak(r.rao.omega_rad_s, Quantity(r.rao, q)).fitted;
    r.rao = MergeRaoTables(r.rao, solve(added));
    r.passes = pass;
    const Measures next = Measure(r.rao, seas);
    Changes(measures, next, &msi_change, &rms_change);
    measures = next;
  }
  if (stopped_by) {
    r.converged = false;
    const bool by_count = std::string(stopped_by) == "frequencies";
    std::ostringstream m;
    m.precision(3);
    m << "adaptive frequency grid stopped at its cap of "
      << (by_count ? std::to_string(o.max_frequencies) + " frequencies" : std::to_string(o.max_passes) + " passes")
      << " before converging (last pass: RAO peak changed by " << 100 * peak_change << " % (tolerance "
      << 100 * o.peak_tolerance << " %) and MSI by " << msi_change << " points (tolerance " << o.msi_tolerance_pct
      << ")); the peak and the MSI depend on the grid: raise " << (by_count ? o.frequencies_key : o.passes_key);
    r.rao.warnings.push_back(m.str());
  }
  return r;
}

sk::RaoTable SweepAdaptively(const sk::RaoSweeper& sweeper, const std::vector<double>& omega_rad_s,
                             const AdaptiveGridOptions& options, const GridSeas* seas) {
  // --profile: the solves count as the periodic solve, the rest of the refinement (the seas of every pass) as
  // the seas.
  const opt::CostTimer timer(opt::CostStage::kSeas);
  const auto solve = [&](const std::vector<double>& w) {
    const opt::CostTimer solve_timer(opt::CostStage::kPeriodicSolve);
    return sweeper.Solve(w);
  };
  sk::RaoTable t = RefineFrequencyGrid(omega_rad_s, solve, options, seas).rao;
  std::vector<std::string> caps = std::move(t.warnings);
  t.warnings = sweeper.Warnings(t, sk::kGridAdvice);
  t.warnings.insert(t.warnings.end(), caps.begin(), caps.end());
  return t;
}

}  // namespace hullopt::eval
