#include "seakeeping/motions/rao_interpolation.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hullopt::sk {

bool IsValidRaoTable(const RaoTable& t, std::string* error) {
  auto fail = [&](const std::string& m) {
    if (error) *error = "RAO table: " + m;
    return false;
  };
  const size_t n = t.omega_rad_s.size();
  if (n < 2) return fail("needs at least 2 frequencies, has " + std::to_string(n));
  if (t.omega_e_rad_s.size() != n || t.heave.size() != n || t.pitch.size() != n)
    return fail("omega, omega_e, heave and pitch must have the same length");
  if (!(t.speed_m_s >= 0.0) || !std::isfinite(t.speed_m_s)) return fail("speed must be >= 0");
  if (!(t.g_m_s2 > 0.0) || !std::isfinite(t.g_m_s2)) return fail("g must be > 0");
  for (size_t i = 0; i < n; ++i) {
    std::ostringstream at;
    at << "row " << i << " (omega = " << t.omega_rad_s[i] << " rad/s): ";
    const double w = t.omega_rad_s[i], we = t.omega_e_rad_s[i];
    if (!std::isfinite(w) || !(w > 0.0)) return fail(at.str() + "omega must be finite and > 0");
    if (i > 0 && !(w > t.omega_rad_s[i - 1])) return fail(at.str() + "omega must increase strictly");
    const double expected = w + w * w * t.speed_m_s / t.g_m_s2;
    if (!(std::abs(we - expected) <= 1e-4 * expected))
      return fail(at.str() + "omega_e must equal omega + omega^2 U/g = " + std::to_string(expected));
    if (!std::isfinite(t.heave[i].real()) || !std::isfinite(t.heave[i].imag()) ||
        !std::isfinite(t.pitch[i].real()) || !std::isfinite(t.pitch[i].imag()))
      return fail(at.str() + "RAO is not finite");
  }
  return true;
}

ComplexRao InterpolateRao(const RaoTable& t, double omega_e) {
  const auto& we = t.omega_e_rad_s;
  if (we.empty() || !(omega_e >= we.front() && omega_e <= we.back()))
    throw std::out_of_range("InterpolateRao: omega_e = " + std::to_string(omega_e) +
                            " rad/s outside the RAO table");
  size_t hi = static_cast<size_t>(std::upper_bound(we.begin(), we.end(), omega_e) - we.begin());
  hi = std::min(std::max<size_t>(hi, 1), we.size() - 1);
  const size_t lo = hi - 1;
  const double f = (omega_e - we[lo]) / (we[hi] - we[lo]);
  return {t.heave[lo] + f * (t.heave[hi] - t.heave[lo]), t.pitch[lo] + f * (t.pitch[hi] - t.pitch[lo])};
}

}  // namespace hullopt::sk
