#pragma once
// The attitude a design's strips are solved at: the one a config gives (hull.attitude, e.g. measured in a
// tank), or with solver.steady_flow: on the running sinkage and trim of calm water on the strips themselves
// (seakeeping/motions/calm_water.h).
#include <string>

#include "evaluation/solver_settings.h"
#include "evaluation/water.h"
#include "parametric_hull/hull_form.h"
#include "parametric_hull/running_attitude.h"

namespace hullopt::eval {

/// `given` (pivot set to the LCG), or with settings.steady_flow the solved running attitude at speed U.
/// Throws InputError naming `where` and 'solver.steady_flow' when both a given attitude and steady_flow are set,
/// or when the calm-water iteration does not converge (trim beyond hull::kMaxTrimDeg, a hull lifting out).
hull::RunningAttitude StripAttitude(const hull::HullForm& at_rest, const hull::MassProperties& mass,
                                    double speed_m_s, const WaterOptions& water, const SolverSettings& settings,
                                    hull::RunningAttitude given, const std::string& where);

/// How many calm-water attitudes StripAttitude has solved since the start of the process (for the checks that
/// a refused config solved nothing).
long CalmWaterSolves();

/// One line for the outputs: "running attitude ... (given | from calm water on the strips)", empty at even keel
/// without steady_flow.
std::string AttitudeNote(const hull::RunningAttitude& attitude, const SolverSettings& settings);

}  // namespace hullopt::eval
