#pragma once
// Gauss–Legendre rules on [0, 1], computed once per order by Newton iteration on P_n and cached.
#include <vector>

namespace hullopt::sk {

struct QuadratureRule {
  std::vector<double> nodes;    ///< in (0, 1), ascending
  std::vector<double> weights;  ///< sum to 1
};

/// The n-point Gauss–Legendre rule on [0, 1] (1 <= n <= 128; throws std::invalid_argument otherwise).
/// Thread-safe; the returned reference stays valid for the program's lifetime.
const QuadratureRule& GaussLegendre01(int n);

}  // namespace hullopt::sk
