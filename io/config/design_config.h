#pragma once
// A design from a config (evaluate, optimize, calibrate, coefficients): the water, hull, speed, solver
// (optional: defaults 40 sections × 14 panels, Cs 0, periodic path) and mass sections read into an
// eval::DesignCase.
#include <string>

#include "evaluation/design_case.h"
#include "evaluation/trial_design.h"
#include "io/config/hull_config.h"
#include "io/config/speed_config.h"
#include "io/config/yaml_map.h"

namespace hullopt::io {

/// The options a design was read from, for callers that build more designs like it (campaign trials).
struct DesignConfig {
  WaterOptions water;
  HullOptions hull;
  SpeedOptions speed;
  eval::SolverSettings solver;
  bool has_frequencies = false;
};

/// The design's `name` key (default `fallback`, usually the config or offsets file's name), not empty.
/// Recorded in config.resolved.yaml, so that a re-run keeps the name.
std::string ParseDesignName(YamlMap& root, const std::string& fallback);

/// Reads water, hull, speed, solver and mass from root and builds the hull. Consumes exactly these keys (the
/// caller calls root.Finish()). With read_speed false the speed is left to the caller (speed_m_s = 0). Errors
/// are InputError naming the file, key and rule. `config` (optional) receives the options read.
eval::DesignCase LoadDesignCase(YamlMap& root, const std::string& config_file, const std::string& name,
                                bool read_speed = true, DesignConfig* config = nullptr);

/// The base of campaign trials from the options of a design read from config_file (mass rule at its defaults).
eval::DesignBasis TrialBasis(const DesignConfig& config, const std::string& config_file);

}  // namespace hullopt::io
