#include "seakeeping/green/gauss_legendre.h"

#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace hullopt::sk {
namespace {

constexpr int kMaxOrder = 128;

QuadratureRule Compute(int n) {
  QuadratureRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < n; ++i) {
    // Tricomi's initial guess for the i-th root of P_n on [−1, 1], then Newton in long double.
    long double x = std::cos(M_PI * (i + 0.75) / (n + 0.5));
    long double dp = 1;
    for (int it = 0; it < 100; ++it) {
      long double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const long double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      const long double dx = p1 / dp;
      x -= dx;
      if (std::fabs(static_cast<double>(dx)) < 1e-19) break;
    }
    // Map [−1, 1] → [0, 1]; the weight of the [−1, 1] rule is 2/((1 − x²) P_n'(x)²).
    rule.nodes[n - 1 - i] = static_cast<double>(0.5L * (1 + x));
    rule.weights[n - 1 - i] = static_cast<double>(1.0L / ((1 - x * x) * dp * dp));
  }
  return rule;
}

}  // namespace

const QuadratureRule& GaussLegendre01(int n) {
  if (n < 1 || n > kMaxOrder)
    throw std::invalid_argument("Gauss-Legendre order must be in 1.." + std::to_string(kMaxOrder) + ", got " +
                                std::to_string(n));
  static std::array<std::unique_ptr<QuadratureRule>, kMaxOrder + 1> cache;
  static std::array<std::once_flag, kMaxOrder + 1> flags;
  std::call_once(flags[n], [n] { cache[n] = std::make_unique<QuadratureRule>(Compute(n)); });
  return *cache[n];
}

}  // namespace hullopt::sk
