#pragma once
// The `speed:` map shared by every command: exactly one of Froude number, knots or metres per second.
#include <string>

#include "io/yaml_map.h"

namespace hullopt::io {

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

/// Reads `speed:` from root ({Fn: 0.75} | {kn: 40} | {m_s: 4.07}). If `required` is false and the key is
/// absent, sets *present (if given) to false and returns a default. Throws InputError for none or several
/// units, unknown keys, non-numbers, and speeds <= 0, Fn > 5 or over 200 kn / 200 m/s.
SpeedOptions ParseSpeed(YamlMap& root, bool required, bool* present = nullptr);

}  // namespace hullopt::io
