#pragma once
// The `hull:` map (docs/config-reference.md) → options, and loading the hull they describe.
//   hull:
//     parametric: {type, displacement_t, L_over_B, B_over_T, Cb, Cp, Cwp, LCB_pct_L, LCF_pct_L, ...}
//     spacing_m: 20          # optional absolute demihull spacing (else parametric.spacing_over_L)
//   or
//     offsets_csv: data/delft372/delft372_offsets.csv   # or stl: file.stl
//     draught_m: 0.15
//     hulls: 2               # 1 monohull, 2 catamaran/SWATH demihulls
//     spacing_m: 0.70        # demihull centreline spacing (needed when hulls = 2)
//     stations: 0            # resample to this many equally spaced stations (0 = keep the file's; STL: 41)
//     length_m: 0            # waterline length L for coefficients (0 = span of the wetted stations)
//   either source may add the steady running attitude (default even keel; parametric_hull/running_attitude.h):
//     attitude: { sinkage_m: 0.0, trim_deg: 0.0 }   # sinkage + down at the CG, trim + bow up
// File paths are relative to the working directory.
#include <string>
#include <vector>

#include "io/config/water_config.h"
#include "io/config/yaml_map.h"
#include "parametric_hull/design_variables.h"
#include "parametric_hull/hull_form.h"
#include "parametric_hull/running_attitude.h"

namespace hullopt::io {

struct HullOptions {
  enum class Source { kParametric, kOffsetsCsv, kStl };
  Source source = Source::kParametric;
  hull::DesignVariables design;  ///< parametric source (rho from water:)
  std::string file;              ///< offsets CSV or STL path
  double draught_m = 0.0;        ///< [m] file sources
  int hulls = 1;                 ///< file sources: 1 or 2
  double spacing_m = 0.0;        ///< [m] demihull centreline spacing (file sources with hulls = 2)
  int stations = 0;              ///< resample to this many stations (0 = as read)
  double length_m = 0.0;         ///< [m] waterline length override for file sources (0 = from the stations)
  /// Running attitude (sinkage, trim; the pivot is set by ApplyHullAttitude). Even keel by default.
  hull::RunningAttitude attitude;
};

/// Parses the `hull:` map of root; water gives the density used for a parametric displacement. Throws
/// InputError naming file, line, key and rule (missing, unknown, wrong type, NaN, out of range, both or
/// neither of parametric / offsets_csv / stl).
HullOptions ParseHullConfig(YamlMap& root, const WaterOptions& water);

/// Builds or reads the hull. File errors are InputError with file and line; a parametric combination that
/// cannot be met becomes InputError "key 'hull.parametric': <rule>" (where = config file for messages).
/// The plausibility rules (io/hull_plausibility.h) are applied to every hull: refusals throw, warnings are
/// appended to *warnings.
hull::HullForm LoadHull(const HullOptions& options, const std::string& config_file,
                        std::vector<std::string>* warnings = nullptr);

/// The hull at options.attitude about pivot_x_m [m from AP] (the centre of gravity): hydrostatics, strips and
/// RAOs of a running hull use this one, the mass and the form coefficients the hull at rest. Even keel returns
/// at_rest unchanged. A refused attitude becomes InputError "CONFIG: key 'hull.attitude': <rule>".
hull::HullForm ApplyHullAttitude(const HullOptions& options, const hull::HullForm& at_rest, double pivot_x_m,
                                 const std::string& config_file);

}  // namespace hullopt::io
