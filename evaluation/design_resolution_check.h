#pragma once
// The resolution check of one computed design: the same design re-run at factor x its sections and panels on
// the same wave frequencies and seas, compared through its RAO peaks and MSI (sk::CompareResolutions). Used by
// evaluate for every computed design and by the campaigns for their best design.
#include <vector>

#include "evaluation/design_case.h"
#include "seakeeping/motions/rao_table.h"
#include "seas/design_evaluation.h"
#include "seas/resolution_check.h"

namespace hullopt::eval {

/// Largest resolution a check may ask for (the strip solver's limits on sections and panels).
constexpr int kMaxCheckSections = 400;
constexpr int kMaxCheckPanels = 100;

/// coarse/coarse_eval: the design's own result at design.solver (its frequencies and seas are reused).
/// cs_override as for ComputeDesignRaos. Throws InputError naming the design when the check's resolution is
/// beyond the solver's limits or the fine result cannot be evaluated.
sk::ResolutionCheck CheckDesignResolution(const DesignCase& design, const sk::RaoTable& coarse,
                                          const sk::DesignEvaluation& coarse_eval,
                                          const std::vector<sk::WaveSpectrum>& spectra,
                                          const std::vector<sk::PassengerPosition>& points,
                                          const sk::EvaluationOptions& options, int factor,
                                          const sk::ResolutionCheckOptions& check, double cs_override = -1.0);

}  // namespace hullopt::eval
