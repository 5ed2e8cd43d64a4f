// Section shapes: the Lewis form reproduces the requested beam, draught and area (numerical area of the mapped
// contour, independent of the closed-form inverse), and impossible requests are refused.
#include <catch2/catch.hpp>
#include <cmath>

#include "seakeeping/sections/section_shapes.h"

namespace {
double HalfArea(const hullopt::sk::HalfContour& c) {  // ∫ y dz by the trapezoid rule
  double a = 0;
  for (std::size_t i = 1; i < c.size(); ++i) a += 0.5 * (c[i][0] + c[i - 1][0]) * (c[i][1] - c[i - 1][1]);
  return a;
}
}  // namespace

TEST_CASE("Lewis form hits beam, draught and area coefficient", "[lewis]") {
  for (auto [B, T, s] : {std::tuple{2.0, 1.0, 0.6}, {2.0, 1.0, M_PI / 4}, {4.0, 1.0, 0.8}, {1.0, 1.0, 0.6}}) {
    const auto c = hullopt::sk::LewisContour(B, T, s, 4000);
    CHECK(c.front()[1] == Approx(-T).epsilon(1e-12));
    CHECK(c.back()[0] == Approx(B / 2).epsilon(1e-12));
    // Trapezoid with 4000 points: relative error ~1e-7; 1e-5 leaves margin.
    CHECK(2 * HalfArea(c) / (B * T) == Approx(s).epsilon(1e-5));
  }
  CHECK_THROWS_AS(hullopt::sk::LewisContour(2.0, 1.0, 1.2, 100), std::domain_error);
}

TEST_CASE("semicircle area", "[shapes]") {
  const auto c = hullopt::sk::SemicircleContour(1.5, 4000);
  CHECK(2 * HalfArea(c) == Approx(M_PI * 1.5 * 1.5 / 2).epsilon(1e-6));
}
