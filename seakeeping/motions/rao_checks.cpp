#include "seakeeping/motions/rao_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace hullopt::sk {

void RequireFiniteRaos(const RaoTable& t) {
  for (std::size_t i = 0; i < t.omega_rad_s.size(); ++i) {
    const std::pair<const char*, std::complex<double>> v[] = {{"heave", t.heave[i]}, {"pitch", t.pitch[i]}};
    for (const auto& [name, z] : v) {
      if (std::isfinite(z.real()) && std::isfinite(z.imag())) continue;
      std::ostringstream m;
      m << name << " RAO at omega = " << t.omega_rad_s[i] << " rad/s (omega_e = " << t.omega_e_rad_s[i]
        << " rad/s) is not finite (the motion equations are singular there)";
      throw std::domain_error(m.str());
    }
  }
}

std::vector<std::string> RaoResonanceWarnings(const RaoTable& t) {
  std::vector<std::string> out;
  for (int q = 0; q < 2; ++q) {
    const auto& v = q == 0 ? t.heave : t.pitch;
    std::size_t at = 0;
    for (std::size_t i = 1; i < v.size(); ++i)
      if (std::abs(v[i]) > std::abs(v[at])) at = i;
    if (v.empty()) continue;
    const char* unit = q == 0 ? " m/m" : " rad/rad";
    const char* name = q == 0 ? "heave" : "pitch";
    if (at > 0 && at + 1 < v.size()) {
      // 1/|X|² through the three samples (Lagrange), its minimum on [ω_{at−1}, ω_{at+1}].
      const double* w = &t.omega_rad_s[at - 1];
      const double y0 = 1 / std::norm(v[at - 1]), y1 = 1 / std::norm(v[at]), y2 = 1 / std::norm(v[at + 1]);
      const double d01 = (y1 - y0) / (w[1] - w[0]), d12 = (y2 - y1) / (w[2] - w[1]);
      const double c2 = (d12 - d01) / (w[2] - w[0]);  // curvature / 2
      if (c2 > 0 && std::isfinite(y0) && std::isfinite(y2)) {
        const double wm = std::clamp(0.5 * (w[0] + w[1]) - d01 / (2 * c2), w[0], w[2]);
        const double ym = y1 + d01 * (wm - w[1]) + c2 * (wm - w[0]) * (wm - w[1]);
        const double fitted = ym > 0 ? 1 / std::sqrt(ym) : std::numeric_limits<double>::infinity();
        // Or no neighbour within the half-power band: the grid has one sample on the resonance, and the fit
        // through tails that need not be a single resonance's cannot be trusted either.
        const double half_power = std::abs(v[at]) / std::sqrt(2.0);
        const bool single = std::abs(v[at - 1]) < half_power && std::abs(v[at + 1]) < half_power;
        if (single || fitted > (1 + kPeakSamplingTolerance) * std::abs(v[at])) {
          std::ostringstream m;
          m.precision(3);
          // No commas: the message goes into CSV notes as it is.
          m << name << " RAO peak is under-sampled by the frequency grid: largest sample " << std::abs(v[at]) << unit
            << " at omega = " << t.omega_rad_s[at] << " rad/s with ";
          if (single)
            m << "both neighbours below 1/sqrt(2) of it (one sample in the half-power band)";
          else if (std::isfinite(fitted))
            m << "a single-mode fit through it and its neighbours peaking at " << fitted << unit << " near omega = "
              << wm << " rad/s";
          else
            m << "a single-mode fit through it and its neighbours unbounded near omega = " << wm << " rad/s";
          m << "; the peak and what integrates through it (accelerations and MSI) depend on the grid: refine "
            << "the frequencies between " << w[0] << " and " << w[2] << " rad/s";
          out.push_back(m.str());
        }
      }
    }
    if (!(std::abs(v[at]) > kResonanceWarningRao)) continue;
    std::ostringstream m;
    m.precision(3);
    m << (q == 0 ? "heave RAO peaks at " : "pitch RAO peaks at ") << std::abs(v[at])
      << (q == 0 ? " m/m" : " rad/rad") << " at omega = " << t.omega_rad_s[at]
      << " rad/s: a lightly damped resonance (fast hulls peak at 1-3; above " << kResonanceWarningRao
      << " the result rests on the damping Cs)";
    out.push_back(m.str());
  }
  return out;
}

}  // namespace hullopt::sk
