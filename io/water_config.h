#pragma once
// The `water:` map shared by every command: density and gravity.
#include <string>

#include "io/yaml_map.h"

namespace hullopt::io {

struct WaterOptions {
  double rho_kg_m3 = 1025.0;  ///< [kg/m^3] sea water by default; 1000 for fresh-water tank data
  double g_m_s2 = 9.81;       ///< [m/s^2]
  bool IsValid(std::string* error) const;
};

/// Reads the optional `water:` map of `root` ({rho_kg_m3, g_m_s2}, defaults above). Throws InputError naming
/// file, line, key and rule for unknown keys, non-numbers and out-of-range values.
WaterOptions ParseWater(YamlMap& root);

}  // namespace hullopt::io
