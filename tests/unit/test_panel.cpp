// Panelling a half contour: normals into the fluid, endpoints on the waterline, the user's panel count, the
// contour's turning carried by the panels, corners as panel end points, and panels no longer than the local
// thickness of a thin part once there are enough of them.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "seakeeping/green/panel.h"

using hullopt::sk::PanelSymmetricSection;

namespace {
std::vector<std::array<double, 2>> Semicircle(int m) {
  std::vector<std::array<double, 2>> half;
  for (int i = 0; i <= m; ++i) {
    const double th = 0.5 * M_PI * i / m;  // keel (θ = 0) to waterline
    half.push_back({std::sin(th), -std::cos(th)});
  }
  half.back() = {1.0, 0.0};
  return half;
}
}  // namespace

TEST_CASE("semicircle panelling: normals point out of the body, ends on the waterline", "[panel]") {
  const auto half = Semicircle(200);
  const auto ps = PanelSymmetricSection(half, 16, 0.0);
  REQUIRE(ps.size() == 16);
  CHECK(ps.front().z1 == 0.0);
  CHECK(ps.back().z2 == 0.0);
  double turn = 0;
  for (const auto& p : ps) {
    const auto n = p.Normal();
    // Outward normal of a circle at the midpoint is the radial direction.
    const double r = std::hypot(p.MidY(), p.MidZ());
    CHECK(n[0] * p.MidY() / r + n[1] * p.MidZ() / r > 0.99);
    // The chord of an arc of the unit circle turning by τ is 2 sin(τ/2) long (the end points lie on the
    // 200-point polyline, whose own vertices are 0.4° apart: up to one vertex is lost per panel end).
    constexpr double kVertexTurn = 0.5 * M_PI / 200;
    CHECK(p.turn_rad == Approx(2 * std::asin(0.5 * p.Length())).margin(kVertexTurn));
    turn += p.turn_rad;
  }
  CHECK(turn == Approx(M_PI).margin(16 * 0.5 * M_PI / 200));  // the whole wetted half circle turns by π
  CHECK_THROWS_AS(PanelSymmetricSection(half, 7, 0.0), std::invalid_argument);
}

TEST_CASE("corners are panel end points and straight panels do not turn", "[panel]") {
  // Box B = 2, T = 1: the bilge corner (1, −1) must be an end point for every even count, and the panels
  // next to it (and to the waterline) are shorter than the uniform spacing.
  for (int n : {4, 6, 14, 28}) {
    const auto ps = PanelSymmetricSection({{0.0, -1.0}, {1.0, -1.0}, {1.0, 0.0}}, n);
    REQUIRE(static_cast<int>(ps.size()) == n);
    bool corner = false;
    for (const auto& p : ps) {
      corner = corner || (p.y2 == Approx(1.0) && p.z2 == Approx(-1.0)) || (p.y1 == Approx(1.0) && p.z1 == Approx(-1.0));
      CHECK(p.turn_rad == 0.0);
    }
    CHECK(corner);
  }
  const auto ps = PanelSymmetricSection({{0.0, -1.0}, {1.0, -1.0}, {1.0, 0.0}}, 14);
  const double uniform = 4.0 / 14;
  CHECK(ps.front().Length() < 0.75 * uniform);  // at the waterline
  double at_corner = 0;
  for (const auto& p : ps)
    if (p.y1 == Approx(1.0) && p.z1 == Approx(-1.0)) at_corner = p.Length();
  CHECK(at_corner > 0);
  CHECK(at_corner < 0.75 * uniform);
}

TEST_CASE("panels on a thin plate shrink to its thickness as the count allows", "[panel]") {
  // Strut (half breadth 0.3 m) over a plate 0.3 m thick and 4 m wide: half girth 4.7 m. With 112 panels the
  // uniform spacing (0.084 m) is below the thickness everywhere; with 56 (0.168 m) the thickness rule must keep
  // the plate faces below their 0.3 m thickness and the strut below its 0.6 m; with 28 the plate panels
  // are shorter than they would be with equal spacing of the plate's share.
  const std::vector<std::array<double, 2>> c{{0.0, -1.0}, {2.0, -1.0}, {2.0, -0.7}, {0.3, -0.7}, {0.3, 0.0}};
  for (int n : {28, 56, 112}) {
    const auto ps = PanelSymmetricSection(c, n);
    REQUIRE(static_cast<int>(ps.size()) == n);
    double plate = 0, strut = 0;
    for (const auto& p : ps) {
      const bool on_plate_face = std::fabs(std::fabs(p.MidZ() + 0.85) - 0.15) < 1e-9;
      if (on_plate_face) plate = std::max(plate, p.Length());
      if (std::fabs(std::fabs(p.MidY()) - 0.3) < 1e-9) strut = std::max(strut, p.Length());
    }
    INFO(n << " panels: longest plate-face panel " << plate << " m, strut panel " << strut << " m");
    if (n >= 56) {
      CHECK(plate <= 0.3);
      CHECK(strut <= 0.6);
    } else {
      CHECK(plate < 0.5);
    }
  }
}

TEST_CASE("a fold thinner than the cut limit is cut at its root, a thicker one kept", "[panel]") {
  // Bottom 1 m out from the keel at 0.5 m depth, a plate sticking out from y = 0.4 m to the bottom's edge and
  // back (thickness e, a fold turning 180° in two corners), then the strut face up to the waterline. Half
  // girth about 2.3 m; 14 panels: the cut limit is 0.1 x 2.3 / 7 = 0.033 m. A 0.005 m plate is cut across
  // its root, so no panel reaches beyond y = 0.4 m by more than the limit; a 0.2 m plate is kept whole and
  // its outer edge (y = 1 m) is a panel end point.
  auto contour = [](double e) {
    return std::vector<std::array<double, 2>>{
        {0.0, -0.5}, {1.0, -0.5}, {1.0, -0.5 + e}, {0.4, -0.5 + e}, {0.4, 0.0}};
  };
  const double limit = 0.1 * 2.3 / 7;  // cut_thickness_fraction x uniform spacing (PanelSpacing defaults)
  auto reach = [](const std::vector<hullopt::sk::Panel>& ps) {
    double y = 0;
    for (const auto& p : ps) y = std::max({y, p.y1, p.y2});
    return y;
  };
  const auto thin = PanelSymmetricSection(contour(0.005), 14);
  const auto thick = PanelSymmetricSection(contour(0.2), 14);
  REQUIRE(thin.size() == 14);
  REQUIRE(thick.size() == 14);
  CHECK(reach(thin) < 0.4 + 2 * limit);
  CHECK(reach(thick) == 1.0);  // the plate's outer corner, exactly
  // Without cutting the thin plate stays (its corner is a panel end point).
  hullopt::sk::PanelSpacing keep;
  keep.cut_thickness_fraction = 0.0;
  CHECK(reach(PanelSymmetricSection(contour(0.005), 14, 0.0, keep)) == 1.0);
}
