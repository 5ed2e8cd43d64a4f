#pragma once
// The resolution check of a computed design (`resolution_check:`): the design re-run at factor x its sections
// and panels on the same frequencies and seas; a design that moves by more than the tolerances carries the
// warning in its RAO table, and so in every output.
#include <string>
#include <vector>

#include "evaluation/design_case.h"
#include "io/report/evaluated_design.h"
#include "io/config/resolution_check_config.h"
#include "seas/design_evaluation.h"

namespace hullopt::app {

/// Fills design->resolution (design->rao and design->evaluation already computed from `computed`). where
/// names the config for messages; Cs overrides the design's when >= 0.
void CheckDesignResolution(const io::ResolutionCheckConfig& check, const std::vector<sk::WaveSpectrum>& spectra,
                           const std::vector<sk::PassengerPosition>& points, const sk::EvaluationOptions& options,
                           const eval::DesignCase& computed, double cs_override, const std::string& where,
                           io::EvaluatedDesign* design);

}  // namespace hullopt::app
