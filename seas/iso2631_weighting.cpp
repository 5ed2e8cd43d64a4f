#include "seas/iso2631_weighting.h"

#include <cmath>
#include <complex>

namespace hullopt::sk {

double Iso2631WfMagnitude(double f_hz) {
  constexpr double kTwoPi = 6.28318530717958647692;
  using C = std::complex<double>;
  const C s(0.0, kTwoPi * f_hz);
  const double w1 = kTwoPi * 0.08, w2 = kTwoPi * 0.63, w4 = kTwoPi * 0.25, w5 = kTwoPi * 0.0625,
               w6 = kTwoPi * 0.10;
  const double q4 = 0.86, q5 = 0.80, q6 = 0.80;
  const double r2 = std::sqrt(2.0);
  const C hh = s * s / (s * s + r2 * w1 * s + w1 * w1);          // high pass
  const C hl = 1.0 / (s * s / (w2 * w2) + r2 * s / w2 + 1.0);    // low pass
  const C ht = 1.0 / (s * s / (w4 * w4) + s / (q4 * w4) + 1.0);  // a–v transition, f3 = ∞
  const C hs = (s * s + w5 * s / q5 + w5 * w5) / (s * s + w6 * s / q6 + w6 * w6);  // upward step
  return std::abs(hh * hl * ht * hs);
}

}  // namespace hullopt::sk
