#pragma once
// SVG plots of a campaign from its evaluation log: convergence and variable traces (optimize), scatter and
// partial-dependence plots (explore).
#include <string>
#include <vector>

#include "optimizer/evaluation_record.h"

namespace hullopt::io {

/// convergence.svg: objective of every produced evaluation (feasible filled, infeasible hollow) and the best
/// feasible objective so far, against the evaluation number; variables.svg: each variable against the
/// evaluation number, with its bounds as the axis range. objective_label names the objective and its unit.
void WriteOptimizePlots(const std::string& dir, const std::vector<opt::EvaluationRecord>& records,
                        const std::vector<std::string>& names, const std::vector<double>& lower,
                        const std::vector<double>& upper, const std::string& objective_label);

/// scatter.svg: objective against each variable (feasible samples; infeasible produced ones hollow), with the
/// partial dependence (mean objective of the feasible samples in ⌊√N⌋ equal-count bins of that variable).
void WriteExplorePlots(const std::string& dir, const std::vector<opt::EvaluationRecord>& records,
                       const std::vector<std::string>& names, const std::string& objective_label);

}  // namespace hullopt::io
