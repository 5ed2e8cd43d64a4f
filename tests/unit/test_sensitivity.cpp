// Sensitivity from an exploration sample against a linear model y = Σ a_i x_i, whose standardised regression
// coefficients are exactly SRC_i = a_i σ_i / σ_y (sample standard deviations) and whose first-order Sobol
// indices equal SRC_i² for independent inputs.
#include <catch2/catch.hpp>
#include <cmath>

#include "optimizer/design_sampling.h"
#include "optimizer/sensitivity.h"

namespace {
double SampleSd(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m += x;
  m /= v.size();
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / (v.size() - 1));
}
}  // namespace

TEST_CASE("SRCs of a linear model are a_i sigma_i / sigma_y", "[sensitivity]") {
  // Least squares on an exact linear model: only rounding error remains.
  constexpr double kRoundoffTol = 1e-10;
  const std::vector<double> a = {3.0, -1.0, 0.5};
  const auto x = hullopt::opt::LatinHypercube(200, 3, 11);
  std::vector<double> y;
  std::vector<std::vector<double>> cols(3);
  for (const auto& p : x) {
    // Variables with different ranges: x0 in [0,1), x1 in [0, 10), x2 in [0, 2).
    const std::vector<double> v = {p[0], 10 * p[1], 2 * p[2]};
    y.push_back(a[0] * v[0] + a[1] * v[1] + a[2] * v[2]);
    for (int j = 0; j < 3; ++j) cols[j].push_back(v[j]);
  }
  std::vector<std::vector<double>> xs;
  for (std::size_t i = 0; i < y.size(); ++i) xs.push_back({cols[0][i], cols[1][i], cols[2][i]});
  const auto s = hullopt::opt::ComputeSensitivity(xs, y, {"a", "b", "c"});
  const double sy = SampleSd(y);
  for (int j = 0; j < 3; ++j) CHECK(s.src[j] == Approx(a[j] * SampleSd(cols[j]) / sy).margin(kRoundoffTol));
  CHECK(s.r_squared == Approx(1.0).margin(kRoundoffTol));
}

TEST_CASE("first-order indices of a linear model approach SRC squared", "[sensitivity]") {
  // Binned (correlation-ratio) estimator with ~sqrt(N) bins: bias of order 1/bins² plus sampling noise;
  // at N = 4096 both are below 0.02 of Var(y).
  constexpr double kEstimatorTol = 0.02;
  const auto x = hullopt::opt::SobolPoints(4096, 3);
  std::vector<double> y;
  for (const auto& p : x) y.push_back(4 * p[0] + 2 * p[1] + 1 * p[2]);
  const auto s = hullopt::opt::ComputeSensitivity(x, y, {"a", "b", "c"});
  // Uniform inputs of equal variance: S_i = a_i² / Σ a_j² = 16/21, 4/21, 1/21.
  CHECK(s.first_order[0] == Approx(16.0 / 21).margin(kEstimatorTol));
  CHECK(s.first_order[1] == Approx(4.0 / 21).margin(kEstimatorTol));
  CHECK(s.first_order[2] == Approx(1.0 / 21).margin(kEstimatorTol));
}

TEST_CASE("degenerate samples are refused with the variable named", "[sensitivity][bad-input]") {
  std::vector<std::vector<double>> x = {{1, 0}, {1, 1}, {1, 2}, {1, 3}, {1, 4}};
  std::vector<double> y = {0, 1, 2, 3, 4};
  CHECK_THROWS_WITH(hullopt::opt::ComputeSensitivity(x, y, {"p", "q"}), Catch::Contains("'p' does not vary"));
  CHECK_THROWS_WITH(hullopt::opt::ComputeSensitivity({{1, 2}}, {1}, {"p", "q"}),
                    Catch::Contains("at least 4"));
}
