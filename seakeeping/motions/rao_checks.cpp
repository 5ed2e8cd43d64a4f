#include "seakeeping/motions/rao_checks.h"

#include <cmath>
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
    if (v.empty() || !(std::abs(v[at]) > kResonanceWarningRao)) continue;
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
