#pragma once
// The optional `compare:` block of a rao config: measured RAOs to draw as markers on rao.svg.
//
//   compare:
//     tank_rao_csv: data/delft372/delft372_tank_rao_fn075.csv   # tank RAO CSV (io/formats/tank_rao_reader.h)
//     label: "tank, Delft 372"                                   # legend text (default: the file name)
//
// A relative path resolves as every data path of a config (io/config/config_path.h). Only the rows at the
// run's Froude number (within kCompareFnTolerance) are drawn; a file without such a row is an error naming
// the speeds it has.
#include <optional>
#include <string>

#include "io/report/rao_plot.h"
#include "io/config/yaml_map.h"

namespace hullopt::io {

/// [-] |Fn_row − Fn_run| that counts as the same speed (the calibrate rule: Fn is given to 2–3 decimals).
constexpr double kCompareFnTolerance = 0.005;

/// The `compare` block as read, before the run's speed is known.
struct RaoComparisonSource {
  std::string file;   ///< tank RAO CSV (io/formats/tank_rao_csv.h)
  std::string label;  ///< legend of the measured points
  std::string where;  ///< "config:line: key 'compare.tank_rao_csv'" for messages
};

/// Reads `compare` of the root map (consuming it, checking its keys); nothing when the block is absent.
std::optional<RaoComparisonSource> ParseRaoComparison(YamlMap& root);

/// The measured points of `source` at the run's Froude number Fn [-] (length_m [m] the L of λ/L and Fn,
/// g_m_s2 [m/s²] gravity). Throws InputError for an unreadable or malformed file or a file with no row at Fn.
MeasuredRao ReadRaoComparison(const RaoComparisonSource& source, double Fn, double length_m, double g_m_s2);

/// Reads `compare` of the root map (consuming it); nothing when the block is absent. Fn [-] is the run's
/// Froude number, length_m [m] the L of λ/L and Fn, g_m_s2 [m/s²] gravity. Throws InputError for an unknown
/// key, an unreadable or malformed file, or a file with no row at Fn.
std::optional<MeasuredRao> ReadRaoComparison(YamlMap& root, double Fn, double length_m, double g_m_s2);

}  // namespace hullopt::io
