#pragma once
// The `water:` map shared by every command: density and gravity.
#include <string>

#include "evaluation/water.h"
#include "io/config/yaml_map.h"

namespace hullopt::io {

using WaterOptions = eval::WaterOptions;

/// Reads the optional `water:` map of `root` ({rho_kg_m3, g_m_s2}, defaults of eval::WaterOptions). Throws
/// InputError naming file, line, key and rule for unknown keys, non-numbers and out-of-range values.
WaterOptions ParseWater(YamlMap& root);

}  // namespace hullopt::io
