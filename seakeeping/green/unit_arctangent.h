#pragma once
// atan(u) for 0 <= u <= 1 without the range checks and slow paths of std::atan2: the strip kernel needs
// arg w in [0, π/4] once per field-point/source-point pair (transient_green.h), where std::atan2 was about
// an eighth of the kernel's time.
//
// Reduction to |v| <= tan(π/16) about c = 0, π/8 or π/4: atan(u) = c + atan(v), v = (u − tan c)/(1 + u tan c),
// then the Taylor series of atan(v) to v^21: the first term left out, v^23/23 <= 3.2e-18, is below half an ulp
// of the result. Accuracy a few ulp against std::atan (unit test).
namespace hullopt::sk {

inline double UnitArctangent(double u) {
  constexpr double kTanPi16 = 0.198912367379658, kTan3Pi16 = 0.6681786379192989;
  constexpr double kTanPi8 = 0.41421356237309503;  // nearest double to √2 − 1
  constexpr double kPi8 = 0.39269908169872414, kPi4 = 0.78539816339744828;
  double c = 0.0, v = u;
  if (u > kTan3Pi16) {
    c = kPi4, v = (u - 1.0) / (u + 1.0);
  } else if (u > kTanPi16) {
    c = kPi8, v = (u - kTanPi8) / (1.0 + u * kTanPi8);
  }
  const double s = v * v;
  double p = -1.0 / 21;
  p = p * s + 1.0 / 19, p = p * s - 1.0 / 17, p = p * s + 1.0 / 15, p = p * s - 1.0 / 13;
  p = p * s + 1.0 / 11, p = p * s - 1.0 / 9, p = p * s + 1.0 / 7, p = p * s - 1.0 / 5;
  p = p * s + 1.0 / 3;
  return c + (v - v * s * p);
}

}  // namespace hullopt::sk
