#pragma once
// ln z as (½ ln|z|², arg z), without the hypot that std::log(std::complex) takes for |z|: the absolute error
// is a few 1e-16, all that the Green-function series need (ln z is added to O(1) terms), and std::log's extra
// care near |z| = 1 costs more than the rest of a series. Outside 1e-290 < |z|² < 1e290 (and for NaN) the
// squared magnitude would lose range, so std::log is used there.
#include <cmath>
#include <complex>

namespace hullopt::sk {

inline std::complex<double> LogWithoutHypot(std::complex<double> z) {
  const double n = std::norm(z);
  if (!(n > 1e-290) || !(n < 1e290)) return std::log(z);
  return {0.5 * std::log(n), std::atan2(z.imag(), z.real())};
}

}  // namespace hullopt::sk
