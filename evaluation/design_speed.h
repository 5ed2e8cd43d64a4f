#pragma once
// The speed of a design as a naval architect gives it: a Froude number, knots or metres per second.
#include <string>

namespace hullopt::eval {

struct SpeedOptions {
  enum class Unit { kFroude, kKnots, kMetresPerSecond };
  Unit unit = Unit::kKnots;
  double value = 0.0;  ///< Fn [-], speed [kn] or speed [m/s], by unit
  /// Ship speed [m/s] for waterline length L [m] and gravity g [m/s^2].
  double MetresPerSecond(double L_m, double g_m_s2) const;
  /// Froude number U/sqrt(g L).
  double Froude(double L_m, double g_m_s2) const;
  bool IsValid(std::string* error) const;
};

constexpr double kMetresPerSecondPerKnot = 1852.0 / 3600.0;

}  // namespace hullopt::eval
