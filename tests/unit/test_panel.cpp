// Panelling a half contour: normals into the fluid, endpoints on the waterline, girth preserved.
#include <catch2/catch.hpp>
#include <cmath>

#include "seakeeping/green/panel.h"

TEST_CASE("semicircle panelling: normals point out of the body, ends on the waterline", "[panel]") {
  std::vector<std::array<double, 2>> half;
  const int m = 200;
  for (int i = 0; i <= m; ++i) {
    const double th = 0.5 * M_PI * i / m;  // keel (θ = 0) to waterline
    half.push_back({std::sin(th), -std::cos(th)});
  }
  half.back() = {1.0, 0.0};
  const auto ps = hullopt::sk::PanelSymmetricSection(half, 16, 0.0);
  REQUIRE(ps.size() == 16);
  CHECK(ps.front().z1 == 0.0);
  CHECK(ps.back().z2 == 0.0);
  for (const auto& p : ps) {
    const auto n = p.Normal();
    // Outward normal of a circle at the midpoint is the radial direction.
    const double r = std::hypot(p.MidY(), p.MidZ());
    CHECK(n[0] * p.MidY() / r + n[1] * p.MidZ() / r > 0.99);
  }
  CHECK_THROWS_AS(hullopt::sk::PanelSymmetricSection(half, 7, 0.0), std::invalid_argument);
}
