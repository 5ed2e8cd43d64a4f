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

/// A resonance peak is under-sampled when the peak of the resonance fitted through the largest sample and its
/// two neighbours exceeds the largest sample by more than this fraction (the resolution check's default peak
/// tolerance: the grid's error is then as large as the strip resolution may be).
constexpr double kPeakSamplingTolerance = 0.03;

/// Warnings for RAO peaks above kResonanceWarningRao (with their value and frequency) and for peaks the
/// frequency grid under-samples; empty when none. A peak is under-sampled when both neighbours of the largest
/// interior sample lie below 1/√2 of it (one sample in the half-power band), or when a single-resonance
/// response, 1/|X|² quadratic in ω (exact for one degree of freedom near its natural frequency), fitted
/// through the three samples peaks above the largest by more than kPeakSamplingTolerance.
std::vector<std::string> RaoResonanceWarnings(const RaoTable& table);

}  // namespace hullopt::sk
