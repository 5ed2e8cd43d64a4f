#pragma once
// The `hullopt section` config (the `section:` block plus `water:`), read strictly into plain
// values. Keys (docs/sections.md):
//
//   section:
//     shape: semicircle     # semicircle {radius_m} | rectangle {beam_m, draught_m}
//     radius_m: 1.0         # | lewis {beam_m, draught_m, area_coefficient}
//                           # | offsets {offsets_csv, x_m [m from AP], draught_m [m above baseline]}
//     count: 1              # sections side by side in the strip ...
//     spacing_m: 3.0        # ... at this centre spacing (required when count > 1)
//     panels: 28            # per section, even (default 28)
//     method: [frequency_domain]   # and/or frequency_domain_direct, time_domain
//     frequencies: { omega_rad_s: [0.5, 1.0, 2.0] }   # or { omega_min_rad_s: 0.5, omega_max_rad_s: 5, count: 20 }
//   water: { rho_kg_m3: 1025, g_m_s2: 9.81 }
#include <string>
#include <vector>

#include "io/config/yaml_map.h"
#include "seakeeping/sections/section_strip.h"

namespace hullopt::io {

struct SectionRunConfig {
  sk::SectionStripSpec strip;
  std::vector<std::string> methods;  ///< "frequency_domain", "frequency_domain_direct", "time_domain" in the order given
  std::vector<double> omegas_rad_s;  ///< [rad/s] increasing order as given
  double rho_kg_m3 = 1025.0;
  double g_m_s2 = 9.81;
  std::string shape_name;  ///< as in the config
};

/// Reads the `section:` and `water:` blocks of root (other top-level blocks of a campaign file are skipped;
/// unknown keys anywhere are refused). Throws InputError naming the key, its value and the rule.
SectionRunConfig ReadSectionConfig(YamlMap& root);

}  // namespace hullopt::io
