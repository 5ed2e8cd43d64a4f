#pragma once
// Checks on computed RAOs, applied where they are computed: a non-finite value never leaves the solver, and a
// resonance far above any real hull's is flagged.
#include <complex>
#include <cstddef>
#include <string>
#include <vector>

#include "seakeeping/motions/oblique_strip_theory.h"
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

/// The largest sample of one RAO and the single-resonance fit through it and its two neighbours.
struct RaoPeakFit {
  std::size_t at = 0;          ///< index of the largest |RAO| sample
  double sampled = 0.0;        ///< its magnitude
  bool fitted_ok = false;      ///< an interior largest sample with finite neighbours and a fit with a minimum
  double fitted = 0.0;         ///< the fitted peak magnitude (infinite when the fit is unbounded); else `sampled`
  double omega_fitted = 0.0;   ///< [rad/s] where the fit peaks, within the neighbours' frequencies
  bool single = false;         ///< both neighbours below 1/√2 of the largest (one sample in the half-power band)
  /// `single`, or the fitted peak above the largest sample by more than the tolerance.
  bool UnderSampled(double tolerance = kPeakSamplingTolerance) const {
    return fitted_ok && (single || fitted > (1 + tolerance) * sampled);
  }
};

/// The peak of |v| over omega (increasing, as long as v): its largest sample and, when it is interior, the
/// single-resonance fit of RaoResonanceWarnings. An empty v gives a default RaoPeakFit.
RaoPeakFit FitRaoPeak(const std::vector<double>& omega_rad_s, const std::vector<std::complex<double>>& v);

/// The under-sampling warning's default advice: the keys of a config's frequency grid.
inline const char* const kGridAdvice = "solver.frequencies, or solver.adaptive_grid: on";

/// Warnings for RAO peaks above kResonanceWarningRao (with their value and frequency) and for peaks the
/// frequency grid under-samples; empty when none. A peak is under-sampled when both neighbours of the largest
/// interior sample lie below 1/√2 of it (one sample in the half-power band), or when a single-resonance
/// response, 1/|X|² quadratic in ω (exact for one degree of freedom near its natural frequency), fitted
/// through the three samples peaks above the largest by more than kPeakSamplingTolerance.
/// The under-sampling warning ends with `advice` (what to change: the config key of the grid).
std::vector<std::string> RaoResonanceWarnings(const RaoTable& table,
                                              const std::string& advice = kGridAdvice);

/// The advice of ObliqueSamplingWarnings: the oblique path solves the given frequencies.
inline const char* const kObliqueGridAdvice = "solver.frequencies: the headings have no adaptive refinement";

/// Warnings for the heave, roll and pitch RAO peaks that the wave-frequency grid under-samples at some heading
/// (the test of RaoResonanceWarnings on each heading's RAOs over the wave frequency, which at every heading of
/// a result is monotone in the encounter frequency): one per mode, naming the headings and the worst peak. A
/// heading whose largest sample of the mode is below 1e-6 of the mode's largest at any heading (a mode the
/// heading does not excite: round-off) is not judged. Empty when none.
std::vector<std::string> ObliqueSamplingWarnings(const ObliqueStripResult& result,
                                                 const std::string& advice = kObliqueGridAdvice);

}  // namespace hullopt::sk
