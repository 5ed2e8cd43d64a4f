#pragma once
// Peak of a sampled RAO curve, refined by a parabola through the largest sample and its two neighbours, so
// that "peak before and after calibration" does not jump from one measured frequency to the next.
#include <vector>

namespace hullopt::opt {

struct RaoPeak {
  double x = 0.0;      ///< abscissa of the peak (same unit as the samples' x: ω_e [rad/s] or λ/L [-])
  double value = 0.0;  ///< peak RAO magnitude (same unit as the samples)
  bool at_edge =
      false;  ///< the largest sample is the first or last one: the true peak may be outside the data
};

/// x need not be sorted (it is sorted here); samples with equal x are averaged. Throws std::invalid_argument
/// when x and y differ in size or are empty. With fewer than three distinct x, or when the parabola does not
/// open downwards or its vertex leaves the bracketing samples, the largest sample is returned.
RaoPeak InterpolatedPeak(std::vector<double> x, std::vector<double> y);

}  // namespace hullopt::opt
