#pragma once
// What `hullopt calibrate` leaves in its output folder besides the plot: calibration.json
// (docs/file-formats.md; keys `Cs`, `Cs_std_error`, `rms_residual`, plus per-point residuals, reduced
// chi-square, peaks before and after) and hull-config snippets with the fitted Cs.
#include <string>
#include <vector>

#include "calibration/calibrate_config.h"
#include "calibration/fit/cs_calibration.h"

namespace hullopt::calib {

/// calibration.json text. `Cs` and `Cs_std_error` are numbers in mode single and lists (one per case, in the
/// order of `cases`) in the other modes.
std::string CalibrationJson(const CalibrateConfig& config, const std::vector<opt::CalibrationCase>& cases,
                            const CsCalibrationResult& r);

/// Hull-config snippet `solver: { Cs: ... }` for case `case_index`, with comments naming the fit.
std::string CalibratedSolverYaml(const CalibrateConfig& config,
                                 const std::vector<opt::CalibrationCase>& cases,
                                 const CsCalibrationResult& r, int case_index);

}  // namespace hullopt::calib
