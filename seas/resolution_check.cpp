#include "seas/resolution_check.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace hullopt::sk {
namespace {

double LargestMagnitude(const std::vector<std::complex<double>>& v) {
  double m = 0.0;
  for (const auto& z : v) m = std::max(m, std::abs(z));
  return m;
}

double RelativeChange(double coarse, double fine) {
  return coarse > 0.0 ? (fine - coarse) / coarse : (fine > 0.0 ? INFINITY : 0.0);
}

}  // namespace

bool ResolutionCheckOptions::IsValid(std::string* error) const {
  if (!(std::isfinite(msi_tolerance_pct) && msi_tolerance_pct > 0.0 && msi_tolerance_pct <= 100.0)) {
    if (error) *error = "msi_tolerance_pct must be in (0, 100] percentage points";
    return false;
  }
  if (!(std::isfinite(peak_tolerance) && peak_tolerance > 0.0 && peak_tolerance < 1.0)) {
    if (error) *error = "peak_tolerance must be in (0, 1)";
    return false;
  }
  return true;
}

ResolutionCheck CompareResolutions(const RaoTable& coarse, const RaoTable& fine,
                                   const DesignEvaluation& coarse_eval, const DesignEvaluation& fine_eval,
                                   int sections, int panels, int fine_sections, int fine_panels,
                                   const ResolutionCheckOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument("resolution check: " + error);
  if (coarse.omega_rad_s.empty() || coarse.heave.size() != coarse.omega_rad_s.size() ||
      coarse.pitch.size() != coarse.omega_rad_s.size())
    throw std::invalid_argument("resolution check: the coarse RAO table is empty or inconsistent");
  if (fine.omega_rad_s.size() != coarse.omega_rad_s.size() || fine.heave.size() != coarse.heave.size() ||
      fine.pitch.size() != coarse.pitch.size())
    throw std::invalid_argument("resolution check: the two RAO tables have different frequency grids");
  for (std::size_t i = 0; i < coarse.omega_rad_s.size(); ++i)
    if (std::abs(fine.omega_rad_s[i] - coarse.omega_rad_s[i]) > 1e-12 * std::max(1.0, coarse.omega_rad_s[i]))
      throw std::invalid_argument("resolution check: the two RAO tables have different frequency grids");
  if (coarse_eval.seas.size() != fine_eval.seas.size())
    throw std::invalid_argument("resolution check: the two evaluations have different sea lists");

  ResolutionCheck r;
  r.sections = sections;
  r.panels = panels;
  r.fine_sections = fine_sections;
  r.fine_panels = fine_panels;
  r.heave_peak = LargestMagnitude(coarse.heave);
  r.heave_peak_fine = LargestMagnitude(fine.heave);
  r.pitch_peak = LargestMagnitude(coarse.pitch);
  r.pitch_peak_fine = LargestMagnitude(fine.pitch);
  r.heave_peak_change = RelativeChange(r.heave_peak, r.heave_peak_fine);
  r.pitch_peak_change = RelativeChange(r.pitch_peak, r.pitch_peak_fine);
  for (std::size_t s = 0; s < coarse_eval.seas.size(); ++s) {
    r.mean_msi_pct.push_back(coarse_eval.seas[s].mean.msi_pct);
    r.fine_mean_msi_pct.push_back(fine_eval.seas[s].mean.msi_pct);
    const double d = std::abs(fine_eval.seas[s].mean.msi_pct - coarse_eval.seas[s].mean.msi_pct);
    if (!(d <= r.max_msi_change_pct)) {  // NaN propagates as "not converged"
      r.max_msi_change_pct = d;
      r.max_msi_change_sea = static_cast<int>(s);
    }
  }
  const bool msi_ok = r.max_msi_change_pct <= options.msi_tolerance_pct;
  const bool heave_ok = std::abs(r.heave_peak_change) <= options.peak_tolerance;
  const bool pitch_ok = std::abs(r.pitch_peak_change) <= options.peak_tolerance;
  r.converged = msi_ok && heave_ok && pitch_ok;
  if (!r.converged) {
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "not converged at %d sections x %d panels: at %d x %d the mean MSI changes by up to %.2f points "
                  "(tolerance %.2f), the heave RAO peak by %+.1f%% (%.3f -> %.3f) and the pitch peak by %+.1f%% "
                  "(%.3f -> %.3f; tolerance %.0f%%)",
                  sections, panels, fine_sections, fine_panels, r.max_msi_change_pct, options.msi_tolerance_pct,
                  100.0 * r.heave_peak_change, r.heave_peak, r.heave_peak_fine, 100.0 * r.pitch_peak_change,
                  r.pitch_peak, r.pitch_peak_fine, 100.0 * options.peak_tolerance);
    r.warning = buf;
  }
  return r;
}

}  // namespace hullopt::sk
