#pragma once
// Checks on computed RAOs, applied where they are computed: a non-finite value never leaves the solver, and a
// resonance far above any real hull's is flagged.
#include <string>
#include <vector>

#include "seakeeping/motions/rao_table.h"

namespace hullopt::sk {

/// Throws std::domain_error naming the quantity and the frequency of the first non-finite RAO.
void RequireFiniteRaos(const RaoTable& table);

/// Heave above this [m/m] or pitch above this [rad/rad] is a lightly damped resonance: fast hulls peak at 1-3
/// in both (the reference paper's Figs. 6-11); near such a peak the result rests on the damping (Cs).
constexpr double kResonanceWarningRao = 5.0;

/// Warnings for RAO peaks above kResonanceWarningRao (with their value and frequency); empty when none.
std::vector<std::string> RaoResonanceWarnings(const RaoTable& table);

}  // namespace hullopt::sk
