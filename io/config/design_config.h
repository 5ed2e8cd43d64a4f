#pragma once
// A design from a config (evaluate, optimize, calibrate, coefficients): the water, hull, speed, solver
// (optional: defaults 40 sections × 14 panels, Cs 0, periodic path) and mass sections read into an
// eval::DesignCase.
#include <functional>
#include <optional>
#include <string>

#include "evaluation/design_case.h"
#include "evaluation/design_spec.h"
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

/// A design's blocks as read: the typed spec, the options it came from, the resolved `mass` map (whose
/// defaults BuildParsedDesign fills in) and the strip kernel asked for (`rao` only offers `impulsive`).
struct ParsedDesign {
  eval::DesignSpec spec;
  DesignConfig config;
  YAML::Node resolved_mass;
  std::string kernel = "transient_green";
  /// With DesignReadOptions::headings: solver.headings_deg (empty when not given) and mass.kxx_m (unset: the
  /// caller's default from the hull).
  std::vector<double> headings_deg;
  std::optional<double> kxx_m;
  /// With headings or DesignReadOptions::roll: solver.roll_damping (ikeda | none, default ikeda) and
  /// solver.roll_amplitude_deg (default 5).
  std::string roll_damping = "none";
  double roll_amplitude_deg = 5.0;
};

/// What a command reads of a design besides the common blocks.
struct DesignReadOptions {
  bool read_speed = true;             ///< false: the speed is left to the caller (speed_m_s = 0)
  bool frequencies_required = false;  ///< solver and solver.frequencies required (rao)
  bool impulsive_kernel = false;      ///< solver.kernel may be `impulsive` (rao)
  /// solver.headings_deg (oblique seas, method strip_theory_stf) and mass.kxx_m may be given (rao); with
  /// headings the centre of gravity's height (mass.kg_m or kg_over_T) is required: roll needs it.
  bool headings = false;
  /// The command computes roll (evaluate's operability.polar): mass.kxx_m, solver.roll_damping and
  /// solver.roll_amplitude_deg may be given and the centre of
  /// gravity's height (mass.kg_m or kg_over_T) is required; `roll_key` names the block that asks for it (its
  /// first component, a key of the config's root, places the error).
  bool roll = false;
  std::string roll_key = "operability.polar";
  /// The design's name read between the speed and the solver, from the hull's options (rao: the hull file's
  /// stem as the default), so that the resolved config keeps its key order.
  std::function<std::string(const HullOptions&)> name_after_hull;
};

/// Reads water, hull, speed, solver and mass from root into a spec, checking every key and rule that needs no
/// hull, and computes nothing (a hull file is read later, by BuildParsedDesign). Consumes exactly these keys:
/// the caller reads its other blocks and calls root.Finish() before building, so that an error anywhere in
/// the config is found before any work.
ParsedDesign ParseDesign(YamlMap& root, const std::string& config_file, const std::string& name,
                         const DesignReadOptions& options = {});

/// Reads the hull file of a file-source design into parsed.spec.hull.given (once; nothing for a parametric
/// one).
void ReadHullFile(ParsedDesign& parsed);

/// Reads the hull file of a file-source design (offsets CSV, STL; its errors name the file and line), builds
/// the design (eval::BuildDesign) and records the mass defaults it took in the resolved config.
eval::DesignCase BuildParsedDesign(ParsedDesign& parsed);

/// ParseDesign then BuildParsedDesign, for callers whose config holds nothing after the design's blocks.
/// Reads water, hull, speed, solver and mass from root and builds the hull. Consumes exactly these keys (the
/// caller calls root.Finish()). With read_speed false the speed is left to the caller (speed_m_s = 0). Errors
/// are InputError naming the file, key and rule. `config` (optional) receives the options read.
eval::DesignCase LoadDesignCase(YamlMap& root, const std::string& config_file, const std::string& name,
                                bool read_speed = true, DesignConfig* config = nullptr);

/// The base of campaign trials from the options of a design read from config_file (mass rule at its defaults).
eval::DesignBasis TrialBasis(const DesignConfig& config, const std::string& config_file);

}  // namespace hullopt::io
