#pragma once
// Resolution check of one design: the same design computed at a coarse and a fine strip resolution (more
// sections and panels), compared through what a designer reads off the result, the heave and pitch RAO peaks
// and the mean MSI in each sea. A design whose result moves by more than the tolerances between the two is
// not converged at the coarse resolution and is flagged in every output, like a near-singular strip warning.
#include <string>
#include <vector>

#include "seakeeping/motions/rao_table.h"
#include "seas/design_evaluation.h"

namespace hullopt::sk {

struct ResolutionCheckOptions {
  /// [percentage points] largest change of the mean MSI in any sea that still counts as converged. One point
  /// is the resolution at which the 14-hull study's designs are ranked (their MSI differ by 1-5 points).
  double msi_tolerance_pct = 1.0;
  /// [-] largest relative change of the heave or pitch RAO peak that counts as converged: the paper's own
  /// resolution statement (40 sections x 14 panels "gave errors approaching 3% in the motions").
  double peak_tolerance = 0.03;
  bool IsValid(std::string* error) const;
};

struct ResolutionCheck {
  int sections = 0, panels = 0;            ///< coarse resolution (the result reported)
  int fine_sections = 0, fine_panels = 0;  ///< resolution of the check
  double heave_peak = 0.0, heave_peak_fine = 0.0;  ///< [m/m] largest |X3/A| over the common frequency grid
  double pitch_peak = 0.0, pitch_peak_fine = 0.0;  ///< [-] largest |X5/(kA)|
  double heave_peak_change = 0.0;   ///< [-] (fine − coarse) / coarse
  double pitch_peak_change = 0.0;   ///< [-]
  double max_msi_change_pct = 0.0;  ///< [points] largest |fine − coarse| of the mean MSI over the seas
  int max_msi_change_sea = -1;      ///< index of that sea in the sea list
  std::vector<double> mean_msi_pct, fine_mean_msi_pct;  ///< [%] mean MSI per sea, coarse and fine
  bool converged = true;
  /// One line with the rule and the numbers when not converged; empty otherwise.
  std::string warning;
};

/// Compares the two results of one design. Both RAO tables must share their frequency grid and both
/// evaluations their sea list. Throws std::invalid_argument for mismatched grids or sea lists, empty tables
/// or invalid options.
ResolutionCheck CompareResolutions(const RaoTable& coarse, const RaoTable& fine,
                                   const DesignEvaluation& coarse_eval, const DesignEvaluation& fine_eval,
                                   int sections, int panels, int fine_sections, int fine_panels,
                                   const ResolutionCheckOptions& options = {});

}  // namespace hullopt::sk
