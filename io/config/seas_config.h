#pragma once
// YAML → sea states, MSI options and passenger points (docs/config-reference.md):
//
//   seas:                                   # non-empty list; each entry one sea ...
//     - { spectrum: jonswap, Hs_m: 3.0, Tz_s: 7.5, gamma: 3.3 }   # Tz_s or Tp_s; gamma default 3.3
//     - { spectrum: bretschneider, Hs_m: 2.0, Tz_s: 6.5 }
//     - sea_state_line: { Hs_m: [0.5, 1.0, 1.5, 2.0, 2.5, 3.0], gamma: 3.3 }  # ... or the paper's line
//                                           #   Tz = 4.5 s + 1.0 s/m · Hs (JONSWAP), expanded in order
//   msi: { model: lloyd, exposure_h: 2, frequency: displacement_m4_m2, acceleration: mean_absolute,
//          iso_km: 0.3333 }                 # all optional (defaults shown)
//   positions:
//     points: [ { name: bridge, x_from_cg_m: 12.0 } ]   # optional user points (forward, lcg, transom always)
//
// Every value is checked with the rule of its options struct; errors are io::InputError naming file, line and
// key.
#include <vector>

#include "io/config/yaml_map.h"
#include "seas/motion_sickness.h"
#include "seas/passenger_positions.h"
#include "seas/wave_spectrum.h"

namespace hullopt::io {

/// Reads the required `seas` list of `root`.
std::vector<sk::SeaState> ReadSeas(YamlMap& root);
/// Reads one sea mapping (spectrum, Hs_m, Tz_s | Tp_s, gamma).
sk::SeaState ReadSeaState(YamlMap& sea);
/// Reads the optional `msi` mapping of `root` (defaults when absent).
sk::MsiOptions ReadMsiOptions(YamlMap& root);
/// Reads the optional `points` list of a `positions` mapping. Checks names (non-empty, unique, not
/// forward/lcg/transom/mean) and, when hull is given, that every point lies on the hull.
std::vector<sk::PassengerPosition> ReadPassengerPoints(YamlMap& positions, const sk::HullExtent* hull);

}  // namespace hullopt::io
