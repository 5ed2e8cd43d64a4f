#pragma once
// Global sensitivity of a campaign's objective to each design variable, estimated from an exploration sample.
#include <string>
#include <vector>

namespace hullopt::opt {

struct SensitivityResult {
  /// Standardised regression coefficients: least-squares fit of (y − ȳ)/σ_y on (x_i − x̄_i)/σ_i. For a linear
  /// y = Σ a_i x_i, SRC_i = a_i σ_i / σ_y exactly; Σ SRC_i² = R² for uncorrelated inputs.
  std::vector<double> src;
  double r_squared = 0.0;  ///< of the linear fit: how much of the variance the SRCs explain
  /// First-order Sobol indices S_i = Var(E[y | x_i]) / Var(y), estimated from the given sample by binning x_i
  /// into ⌊√N⌋ equal-count bins (correlation ratio). Equal to SRC_i² for a linear model; noisy for small N.
  std::vector<double> first_order;
  int samples = 0;  ///< samples used
};

/// x: N samples of d variables; y: N objective values. Needs N >= d + 2 and non-constant columns; throws
/// std::invalid_argument otherwise (the message names the variable).
SensitivityResult ComputeSensitivity(const std::vector<std::vector<double>>& x, const std::vector<double>& y,
                                     const std::vector<std::string>& names);

}  // namespace hullopt::opt
