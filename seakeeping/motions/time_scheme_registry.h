#pragma once
// The time-marching schemes by name: the enum the solver options hold, the names a config gives, and the
// factory that builds a scheme from its kind (docs/ship-motions.md, "Time schemes").
//   weighted_average_trapezoid  passes repeated until the acceleration settles: the implicit trapezoid
//                               solution (default; stable for any w with |1 − w(1 + A/M)| < 1)
//   paper_single_pass           one weighted-average pass per step, as the paper describes the scheme
#include <memory>
#include <string>
#include <vector>

#include "seakeeping/motions/time_scheme.h"
#include "seakeeping/motions/weighted_average_newmark.h"

namespace hullopt::sk {

enum class TimeSchemeKind { kWeightedAverageTrapezoid, kPaperSinglePass };

/// The names, default first.
std::vector<std::string> TimeSchemeNames();
/// The name of a kind.
std::string TimeSchemeName(TimeSchemeKind kind);
/// The kind of a name; false (and *kind untouched) for an unknown name.
bool FindTimeScheme(const std::string& name, TimeSchemeKind* kind);

/// The scheme of that kind. weighted_average_trapezoid uses all of parameters; paper_single_pass uses the
/// hydrodynamic fraction and makes one pass whatever parameters.max_passes. Throws std::invalid_argument for
/// invalid parameters.
std::unique_ptr<TimeScheme> MakeTimeScheme(TimeSchemeKind kind, const WeightedAverageParameters& parameters);

}  // namespace hullopt::sk
