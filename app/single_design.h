#pragma once
// One design read from a hull config with the defaults of io/config/design_defaults.h and evaluated in its
// seas: what `hullopt design` writes and what a campaign's report sets beside each other (baseline and best).
#include <functional>
#include <string>
#include <vector>

#include "evaluation/design_case.h"
#include "io/report/evaluated_design.h"
#include "io/config/resolution_check_config.h"
#include "io/config/yaml_map.h"
#include "seas/design_evaluation.h"

namespace hullopt::app {

struct SingleDesign {
  eval::DesignCase design;
  io::EvaluatedDesign evaluated;
  sk::EvaluationOptions options;
  std::vector<sk::WaveSpectrum> spectra;
  std::vector<sk::PassengerPosition> points;
  io::ResolutionCheckConfig resolution;
  std::vector<std::string> notes;  ///< defaults taken, blocks skipped
};

/// Reads root (skipping other commands' blocks, filling the defaults; root.Finish() when `strict`, else keys of
/// other commands are left unread), then computes the RAOs and evaluates them (cost estimate first: `command`
/// names it). before_work runs after the input is read and before the strip work (output-folder checks).
SingleDesign EvaluateSingleDesign(io::YamlMap& root, const std::string& name, const std::string& command,
                                  bool strict, const std::function<void()>& before_work = {});

/// The speed in knots [kn] of a design.
double SpeedKnots(const eval::DesignCase& design);

}  // namespace hullopt::app
