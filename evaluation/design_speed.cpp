#include "evaluation/design_speed.h"

#include <cmath>

namespace hullopt::eval {

double SpeedOptions::MetresPerSecond(double L_m, double g_m_s2) const {
  switch (unit) {
    case Unit::kFroude:
      return value * std::sqrt(g_m_s2 * L_m);
    case Unit::kKnots:
      return value * kMetresPerSecondPerKnot;
    case Unit::kMetresPerSecond:
      return value;
  }
  return value;
}

double SpeedOptions::Froude(double L_m, double g_m_s2) const {
  return MetresPerSecond(L_m, g_m_s2) / std::sqrt(g_m_s2 * L_m);
}

bool SpeedOptions::IsValid(std::string* error) const {
  const double max = unit == Unit::kFroude ? 5.0 : 200.0;
  if (!(value > 0.0 && value <= max)) {
    if (error) *error = "speed = " + std::to_string(value) + ": must be > 0 and <= " + std::to_string(max);
    return false;
  }
  return true;
}

}  // namespace hullopt::eval
