#pragma once
// The `speed:` map shared by every command: exactly one of Froude number, knots or metres per second.
#include <string>

#include "evaluation/design_speed.h"
#include "io/config/yaml_map.h"

namespace hullopt::io {

using SpeedOptions = eval::SpeedOptions;
using eval::kMetresPerSecondPerKnot;

/// Reads `speed:` from root ({Fn: 0.75} | {kn: 40} | {m_s: 4.07}). If `required` is false and the key is
/// absent, sets *present (if given) to false and returns a default. Throws InputError for none or several
/// units, unknown keys, non-numbers, and speeds <= 0, Fn > 5 or over 200 kn / 200 m/s.
SpeedOptions ParseSpeed(YamlMap& root, bool required, bool* present = nullptr);

}  // namespace hullopt::io
