#pragma once
// The `calibrate:` section of a config (and the speeds it fits), read strictly through io::YamlMap.
//
//   speed: { Fn: 0.75 }                 # the speed the data must have; several: calibrate.speeds_Fn: [0.5,
//   0.75] calibrate:
//     data: [data/delft372/delft372_tank_rao_fn075.csv]   # one hull (the config's own) ...
//     hulls:                            # ... or several hulls (needed for mode linear_in_parameter)
//       - { name: A, parameter: 1.5, data: [a.csv], model: {...} }
//     parameter_name: B_over_T          # name of p in Cs = a + b·p (reports only), default "p"
//     mode: single                      # single | per_speed | linear_in_parameter
//     weights: { heave: 1.0, pitch: 1.0 }
//     residual: absolute                # absolute | relative (residual divided by the measured RAO)
//     loss: { type: none, scale: 1.0 }  # none | huber | cauchy; scale in residual units
//     use_phases: false
//     Cs_initial: 0.05
//     slope_initial: 0.0                # start of b in mode linear_in_parameter
//     max_iterations: 100
//     model: { synthetic_oscillator: { heave_natural_rad_s: 8.1, ... } }   # TEST/DEMO model, see below
//
// `model` selects the RAO model: absent means hullopt's strip solver for the hull of the config (wired in by
// calibration/calibration_model.cpp); `synthetic_oscillator` is the damped-oscillator stand-in of
// calibration/fit/synthetic_oscillator_rao.h, for tests and demonstrations only.
#include <optional>
#include <string>
#include <vector>

#include "io/config/yaml_map.h"
#include "calibration/fit/cs_calibration.h"
#include "calibration/fit/synthetic_oscillator_rao.h"

namespace hullopt::calib {

struct CalibrateHull {
  std::string name;                                          ///< "" for the single-hull form
  double parameter = 0.0;                                    ///< p of Cs = a + b·p
  std::vector<std::string> data_files;                       ///< tank RAO CSV files (paths as resolved)
  std::optional<SyntheticOscillatorOptions> synthetic;  ///< test/demo model, when given
};

struct CalibrateConfig {
  std::vector<double> speeds_Fn;  ///< [-] speeds the data may have
  std::string parameter_name = "p";
  CsCalibrationOptions options;
  std::vector<CalibrateHull> hulls;  ///< one for the `data:` form
};

/// Reads `speed` (or `calibrate.speeds_Fn`) and `calibrate` from the root mapping (keys are marked consumed;
/// the caller calls root.Finish()). Data paths that do not exist relative to the working folder but do
/// relative to the config file's folder are resolved there. Throws io::InputError with file, line, key and rule.
CalibrateConfig ReadCalibrateConfig(io::YamlMap& root);

}  // namespace hullopt::calib
