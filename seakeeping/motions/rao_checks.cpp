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

RaoPeakFit FitRaoPeak(const std::vector<double>& omega, const std::vector<std::complex<double>>& v) {
  RaoPeakFit f;
  if (v.empty()) return f;
  for (std::size_t i = 1; i < v.size(); ++i)
    if (std::abs(v[i]) > std::abs(v[f.at])) f.at = i;
  f.sampled = f.fitted = std::abs(v[f.at]);
  f.omega_fitted = omega[f.at];
  if (f.at == 0 || f.at + 1 >= v.size()) return f;
  // 1/|X|² through the three samples (Lagrange), its minimum on [ω_{at−1}, ω_{at+1}].
  const double* w = &omega[f.at - 1];
  const double y0 = 1 / std::norm(v[f.at - 1]), y1 = 1 / std::norm(v[f.at]), y2 = 1 / std::norm(v[f.at + 1]);
  const double d01 = (y1 - y0) / (w[1] - w[0]), d12 = (y2 - y1) / (w[2] - w[1]);
  const double c2 = (d12 - d01) / (w[2] - w[0]);  // curvature / 2
  if (!(c2 > 0 && std::isfinite(y0) && std::isfinite(y2))) return f;
  const double wm = std::clamp(0.5 * (w[0] + w[1]) - d01 / (2 * c2), w[0], w[2]);
  const double ym = y1 + d01 * (wm - w[1]) + c2 * (wm - w[0]) * (wm - w[1]);
  f.fitted_ok = true;
  f.fitted = ym > 0 ? 1 / std::sqrt(ym) : std::numeric_limits<double>::infinity();
  f.omega_fitted = wm;
  // Or no neighbour within the half-power band: the grid has one sample on the resonance, and the fit through
  // tails that need not be a single resonance's cannot be trusted either.
  const double half_power = f.sampled / std::sqrt(2.0);
  f.single = std::abs(v[f.at - 1]) < half_power && std::abs(v[f.at + 1]) < half_power;
  return f;
}

std::vector<std::string> RaoResonanceWarnings(const RaoTable& t, const std::string& advice) {
  std::vector<std::string> out;
  for (int q = 0; q < 2; ++q) {
    const auto& v = q == 0 ? t.heave : t.pitch;
    if (v.empty()) continue;
    const RaoPeakFit f = FitRaoPeak(t.omega_rad_s, v);
    const char* unit = q == 0 ? " m/m" : " rad/rad";
    const char* name = q == 0 ? "heave" : "pitch";
    if (f.UnderSampled()) {
      std::ostringstream m;
      m.precision(3);
      // No commas: the message goes into CSV notes as it is.
      m << name << " RAO peak is under-sampled by the frequency grid: largest sample " << f.sampled << unit
        << " at omega = " << t.omega_rad_s[f.at] << " rad/s with ";
      if (f.single)
        m << "both neighbours below 1/sqrt(2) of it (one sample in the half-power band)";
      else if (std::isfinite(f.fitted))
        m << "a single-mode fit through it and its neighbours peaking at " << f.fitted << unit << " near omega = "
          << f.omega_fitted << " rad/s";
      else
        m << "a single-mode fit through it and its neighbours unbounded near omega = " << f.omega_fitted << " rad/s";
      m << "; the peak and what integrates through it (accelerations and MSI) depend on the grid: refine "
        << "the frequencies between " << t.omega_rad_s[f.at - 1] << " and " << t.omega_rad_s[f.at + 1] << " rad/s ("
        << advice << ")";
      out.push_back(m.str());
    }
    if (!(f.sampled > kResonanceWarningRao)) continue;
    std::ostringstream m;
    m.precision(3);
    m << (q == 0 ? "heave RAO peaks at " : "pitch RAO peaks at ") << f.sampled
      << (q == 0 ? " m/m" : " rad/rad") << " at omega = " << t.omega_rad_s[f.at]
      << " rad/s: a lightly damped resonance (fast hulls peak at 1-3; above " << kResonanceWarningRao
      << " the result rests on the damping Cs)";
    out.push_back(m.str());
  }
  return out;
}

}  // namespace hullopt::sk
