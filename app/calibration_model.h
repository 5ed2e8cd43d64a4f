#pragma once
// The RAO model of `hullopt calibrate`: the one place where the ship-motion solver is plugged into the Cs
// fit.
#include <vector>

#include "io/config/calibrate_config.h"
#include "io/config/yaml_map.h"
#include "optimizer/cs_calibration.h"

namespace hullopt::app {

/// Model for the cases of a parsed calibrate config (cases hull by hull in config order, speed by speed; each
/// names its hull in CalibrationCase::hull). `root` is the whole config: a real-solver model reads the hull,
/// mass, water and solver sections from it and checks the whole config (root.Finish()) before it builds the
/// hull and the strip kernels. A hull with `model: { synthetic_oscillator: ... }` gets the test/demo
/// oscillator. Throws io::InputError. `warnings` (optional) receives the cases outside the strip method's
/// validity range (sk::ValidityWarnings).
opt::CsRaoModel MakeCalibrationModel(io::YamlMap& root, const io::CalibrateConfig& config,
                                     const std::vector<opt::CalibrationCase>& cases,
                                     std::vector<std::string>* warnings = nullptr);

}  // namespace hullopt::app
