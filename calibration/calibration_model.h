#pragma once
// The RAO model of `hullopt calibrate`: the one place where the ship-motion solver is plugged into the Cs
// fit.
#include <functional>
#include <string>
#include <vector>

#include "calibration/calibrate_config.h"
#include "calibration/fit/cs_calibration.h"
#include "io/config/run_cost.h"
#include "io/config/yaml_map.h"

namespace hullopt::calib {

/// Model for the cases of a parsed calibrate config (cases hull by hull in config order, speed by speed; each
/// names its hull in opt::CalibrationCase::hull). `root` is the whole config: a real-solver model reads the hull,
/// mass, water and solver sections from it and checks the whole config (root.Finish()) before it builds the
/// hull and the strip kernels. A hull with `model: { synthetic_oscillator: ... }` gets the test/demo
/// oscillator. Throws io::InputError. `warnings` (optional) receives the cases outside the strip method's
/// validity range (sk::ValidityWarnings). `check_cost` (optional; the command's cost check) is called with
/// the strip-solver work of a time-domain model before its kernels are built, and may throw to refuse it.
CsRaoModel MakeCalibrationModel(io::YamlMap& root, const CalibrateConfig& config,
                                const std::vector<opt::CalibrationCase>& cases,
                                std::vector<std::string>* warnings = nullptr,
                                const std::function<void(const io::StripWork&)>& check_cost = {});

}  // namespace hullopt::calib
