#pragma once
// The `water:` map shared by every command: density and gravity.
#include <string>

#include "evaluation/validity_envelope.h"
#include "evaluation/water.h"
#include "io/config/yaml_map.h"

namespace hullopt::io {

using WaterOptions = eval::WaterOptions;

/// Reads the optional `water:` map of `root` ({rho_kg_m3, g_m_s2}, defaults of eval::WaterOptions). Throws
/// InputError naming file, line, key and rule for unknown keys, non-numbers and out-of-range values.
WaterOptions ParseWater(YamlMap& root);

/// Fails at `key` of map when value lies beyond the hard limit of its validity-envelope rule
/// (evaluation/validity_envelope.h); values between the flag and the hard limit are flagged where the design is
/// checked as a whole.
void RefuseOutsideEnvelope(const YamlMap& map, const std::string& key, eval::EnvelopeQuantity q, double value);

}  // namespace hullopt::io
