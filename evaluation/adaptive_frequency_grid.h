#pragma once
// A wave-frequency grid that resolves itself: RAOs are solved on a starting grid (the default design grid or
// the user's solver.frequencies), then frequencies are inserted where the response changes fast and only those
// are solved and merged, pass by pass, until the RAO peaks and the integrals through them have converged.
//
// Per pass, the frequencies inserted are
//   - around each heave and pitch RAO peak whose single-resonance fit (sk::FitRaoPeak, rao_checks.h) is
//     under-sampled or moved by more than peak_tolerance since the last pass: the midpoints between the largest
//     sample and its two neighbours (one step into the half-power band on each side) and the fitted peak's
//     frequency;
//   - between samples where the integrand of the acceleration variance, S(ω) ω_e⁴ |X3 − x k X5|², at each
//     passenger position in each sea, is integrated differently by the trapezoid rule and by the parabola
//     through the interval and its neighbours (Simpson's error estimate): the intervals of largest disagreement
//     are halved until the disagreement left is below integrand_tolerance of the integral.
// The grid has converged when (a) no peak is under-sampled and the fitted peak heights changed by less than
// peak_tolerance in the last pass, and (b) the MSI changed by less than msi_tolerance_pct points and the rms
// acceleration by less than rms_tolerance (relative) in every sea at every position in the last pass; or
// when the indicators above find nothing to insert (the starting grid was fine). A pass cap and a frequency
// cap bound the cost; hitting one leaves a warning naming the config key that raises it.
#include <functional>
#include <string>
#include <vector>

#include "seakeeping/motions/rao_checks.h"
#include "seakeeping/motions/rao_solver.h"
#include "seakeeping/motions/rao_table.h"
#include "seas/design_evaluation.h"

namespace hullopt::eval {

struct AdaptiveGridOptions {
  /// Off: the starting grid is solved as it is (the results of a fixed grid, bitwise).
  bool enabled = true;
  /// Relative change of a fitted RAO peak between passes, and the fit's excess over the largest sample, below
  /// which a peak is resolved: the under-sampling warning's own tolerance (3 %, as large as the strip
  /// resolution's error may be), so a converged grid never carries that warning.
  double peak_tolerance = sk::kPeakSamplingTolerance;
  /// Change of any MSI [percentage points] between passes below which the integrals have converged: 0.05
  /// points is a tenth of the MSI's own rounding in reports (one decimal) and far below the differences
  /// between designs a campaign ranks.
  double msi_tolerance_pct = 0.05;
  /// Relative change of any rms acceleration between passes below which it has converged: 0.5 %, the
  /// accuracy of the acceleration measurements the method is validated against is several per cent.
  double rms_tolerance = 0.005;
  /// Estimated quadrature error left (trapezoid vs parabola, summed over intervals) as a fraction of each
  /// acceleration integral: 0.5 %, matching rms_tolerance (σ changes by half the variance's relative change).
  double integrand_tolerance = 0.005;
  /// Refinement passes after the starting grid (config key solver.adaptive_grid_max_passes): each at least
  /// halves the spacing where it inserts, so 6 passes resolve a peak 64x narrower than the starting step.
  int max_passes = 6;
  /// Frequencies in the grid at most (config key solver.adaptive_grid_max_frequencies): the default design
  /// grid's own upper count (kDesignGridMaxCount), so a refined grid costs at most what the largest fixed one did.
  int max_frequencies = 400;
  /// The config keys named by the cap warnings.
  std::string passes_key = "solver.adaptive_grid_max_passes";
  std::string frequencies_key = "solver.adaptive_grid_max_frequencies";
  /// Tolerances > 0 and finite, max_passes in [1, 50], max_frequencies in [3, 10000].
  bool IsValid(std::string* error) const;
};

/// What the grid must resolve besides the RAO peaks: the MSI and rms accelerations of these seas at the
/// standard positions of `hull` and the user points (sk::EvaluateDesign). No spectra: the peaks only.
struct GridSeas {
  std::vector<sk::WaveSpectrum> spectra;
  sk::HullExtent hull;
  std::vector<sk::PassengerPosition> points;
  sk::EvaluationOptions options;
};

/// Solves RAOs at a list of increasing wave frequencies (rad/s).
using RaoSolve = std::function<sk::RaoTable(const std::vector<double>& omega_rad_s)>;

struct AdaptiveGridResult {
  sk::RaoTable rao;                   ///< on the refined grid; warnings: the cap warnings only
  int passes = 0;                     ///< refinement passes run (0: the starting grid was kept)
  std::size_t start_count = 0;        ///< frequencies of the starting grid
  bool converged = true;              ///< false when a cap stopped the refinement
};

/// RAOs on the starting grid omega_rad_s (increasing, > 0), refined as described above by solving only the
/// inserted frequencies with `solve` (one call per pass) and merging. With options.enabled false, or fewer
/// than 3 starting frequencies (no peak or interval to judge): one call on the starting grid. seas may be null
/// (peaks only). Throws std::invalid_argument for invalid options; what `solve` and sk::EvaluateDesign throw
/// passes through.
AdaptiveGridResult RefineFrequencyGrid(const std::vector<double>& omega_rad_s, const RaoSolve& solve,
                                       const AdaptiveGridOptions& options, const GridSeas* seas = nullptr);

/// RefineFrequencyGrid solving with the sweeper (its set-up reused by every pass); the table carries the
/// sweeper's warnings for the refined grid (kernel, resonance: sk::RaoSweeper::Warnings), then the cap warnings.
sk::RaoTable SweepAdaptively(const sk::RaoSweeper& sweeper, const std::vector<double>& omega_rad_s,
                             const AdaptiveGridOptions& options, const GridSeas* seas = nullptr);

/// The tables merged into one increasing in ω (b's frequencies are not in a); speed, g and a's warnings kept.
sk::RaoTable MergeRaoTables(const sk::RaoTable& a, const sk::RaoTable& b);

}  // namespace hullopt::eval
