#pragma once
// The `operability:` block of `hullopt evaluate` and the scatter-diagram CSV it names.
//
//   operability:
//     scatter_csv: data/route/scatter.csv     # relative to the working folder or the config
//     probabilities: fraction                 # fraction | percent | per_mille | per_100000 (how the table is printed)
//     spectrum: jonswap                       # jonswap | bretschneider, gamma: 3.3 (JONSWAP only)
//     criteria:                               # non-empty list
//       - { msi_max_pct: 20, position: mean }
//       - { nordforsk: transit_passengers, position: lcg }   # NORDFORSK 1987 rms acceleration limit
//       - { rms_accel_max_g: 0.10, position: forward, name: crew }
//     polar:                                  # optional: operability over speeds x headings (oblique seas)
//       speeds_kn: [10, 20, 30, 40]           # >= 0
//       headings_deg: [90, 120, 150, 180]     # [0, 360): 180 head seas, 90 beam seas from starboard
//       criteria:                             # non-empty list; each one limit, with its source
//         - { rms_vertical_accel_max_g: 0.275, position: forward, source: "NORDFORSK 1987 ..." }
//         - { rms_lateral_accel_max_g: 0.10, position: forward, z_m: 2.0 }  # y_m, z_m from the CG
//         - { roll_rms_max_deg: 4.0 }
//         - { msi_max_pct: 10, position: mean }
//
// Scatter CSV: a matrix. `#` lines are comments. The first row starts with `Hs_m\Tz_s` (or `Hs_m\Tp_s`; `/`
// also accepted) followed by the period of each column [s]; every further row is Hs [m] followed by the
// probability of each cell (empty = 0). Cell centres, not bin edges.
#include <string>
#include <vector>

#include "io/config/yaml_map.h"
#include "evaluation/operability_polar.h"
#include "seas/operability.h"

namespace hullopt::io {

/// Reads a scatter CSV, multiplying every cell by `scale` (1, 0.01, 0.001). Throws InputError naming the file
/// and line for an unreadable file, a bad header, non-numbers, negative cells or no non-empty cell.
sk::ScatterDiagram ReadScatterCsv(const std::string& path, double scale);

/// operability.polar: the speeds, headings and criteria (options.omega_rad_s is left to the caller).
struct OperabilityPolarConfig {
  bool present = false;
  std::vector<double> speeds_kn;
  eval::PolarOptions options;
  std::vector<eval::PolarCriterion> criteria;
  std::string where;  ///< "config:line: key 'operability.polar'"
};

struct OperabilityConfig {
  bool present = false;
  OperabilityPolarConfig polar;
  std::string scatter_csv;  ///< as resolved
  sk::ScatterDiagram diagram;
  std::vector<sk::OperabilityCriterion> criteria;
};

/// Reads the optional `operability:` block; checks the diagram (probabilities sum to 1 within
/// sk::kScatterProbabilitySumTol, every cell a valid sea) and the criteria (positions among
/// forward/lcg/transom/mean and `user_points`) and the polar's speeds, headings and criteria. Throws InputError naming the key or the CSV line.
OperabilityConfig ParseOperability(YamlMap& root, const std::vector<sk::PassengerPosition>& user_points);

}  // namespace hullopt::io
