// Interpolated RAO peak against exact parabolas (the parabola through three samples of a parabola is the
// parabola).
#include <catch2/catch.hpp>

#include "optimizer/rao_peak.h"

using hullopt::opt::InterpolatedPeak;

namespace {
// Exact arithmetic up to round-off of a few operations on O(1) numbers.
constexpr double kRoundOff = 1e-12;
}  // namespace

TEST_CASE("peak of sampled parabola is its vertex, unequal spacing, unsorted input", "[peak]") {
  auto f = [](double x) { return 3.0 - 2.0 * (x - 1.23) * (x - 1.23); };
  std::vector<double> x = {1.5, 1.0, 1.1, 1.32, 0.8, 2.0};
  std::vector<double> y;
  for (double v : x) y.push_back(f(v));
  const auto p = InterpolatedPeak(x, y);
  CHECK(p.x == Approx(1.23).margin(kRoundOff));
  CHECK(p.value == Approx(3.0).margin(kRoundOff));
  CHECK_FALSE(p.at_edge);
}

TEST_CASE("monotone data: the edge sample, flagged", "[peak]") {
  const auto p = InterpolatedPeak({1, 2, 3}, {0.5, 1.0, 2.0});
  CHECK(p.x == 3.0);
  CHECK(p.value == 2.0);
  CHECK(p.at_edge);
}

TEST_CASE("repeat runs at the same abscissa are averaged", "[peak]") {
  // Samples of 1 − (x − 2)² at 1, 2, 3 with the x = 2 sample measured twice (0.9 and 1.1, mean 1.0).
  const auto p = InterpolatedPeak({1, 2, 2, 3}, {0.0, 0.9, 1.1, 0.0});
  CHECK(p.x == Approx(2.0).margin(kRoundOff));
  CHECK(p.value == Approx(1.0).margin(kRoundOff));
}

TEST_CASE("size mismatch and empty input are refused", "[peak][bad-input]") {
  CHECK_THROWS_AS(InterpolatedPeak({1, 2}, {1}), std::invalid_argument);
  CHECK_THROWS_AS(InterpolatedPeak({}, {}), std::invalid_argument);
}
