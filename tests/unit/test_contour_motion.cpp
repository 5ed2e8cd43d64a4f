// The contour motion of a strip (seakeeping/strip/contour_motion.h) against closed forms: a semicircle whose
// radius grows at a constant rate c, panelled the same way at every step (the panelling rules are
// scale-free), so that the steps are similar polygons about the centre and chord j of every step is parallel
// to chord j of the others. The gap between the parallel lines of chord j at radii R and R' is
// (R'/R − 1) d_j, d_j the distance of the chord's line from the centre at R, so the normal speed is c d_j/R;
// the waterline points move outward at c.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "seakeeping/green/panel.h"
#include "seakeeping/sections/section_shapes.h"
#include "seakeeping/strip/contour_motion.h"

using namespace hullopt::sk;

namespace {
std::vector<std::vector<Panel>> GrowingSemicircle(int steps, double r0, double c, double dt, double y_centre) {
  std::vector<std::vector<Panel>> out;
  for (int n = 0; n < steps; ++n) out.push_back(PanelSymmetricSection(SemicircleContour(r0 + c * n * dt), 14, y_centre));
  return out;
}
}  // namespace

TEST_CASE("contour motion of a growing semicircle", "[unit][contour_motion]") {
  // Chords of one ray pair are parallel: the offsets are exact up to round-off; the central difference of a
  // linear growth is exact too.
  constexpr double kRoundOff = 1e-10;
  const double r0 = 0.5, c = 0.3, dt = 0.05;
  for (double yc : {0.0, 1.5}) {
    const auto steps = GrowingSemicircle(5, r0, c, dt, yc);
    for (int n : {0, 2, 4}) {  // forward, central and backward differences
      const ContourMotion m = StepContourMotion(steps, n, dt);
      const double R = r0 + c * n * dt;
      REQUIRE(m.normal_speed_m_s.size() == steps[n].size());
      for (std::size_t j = 0; j < steps[n].size(); ++j) {
        const Panel& q = steps[n][j];
        const double d = std::fabs(q.Normal()[0] * (q.MidY() - yc) + q.Normal()[1] * q.MidZ());
        CHECK(m.normal_speed_m_s[j] == Approx(c * d / R).margin(kRoundOff));
      }
      REQUIRE(m.waterline.size() == 2);
      double outward_sum = 0;
      for (const auto& w : m.waterline) {
        CHECK(w.speed_m_s == Approx(c).margin(kRoundOff));
        CHECK(std::fabs(w.y_m - yc) == Approx(R).margin(kRoundOff));
        CHECK(w.outward * (w.y_m - yc) > 0);  // the free surface lies away from the body
        outward_sum += w.outward;
      }
      CHECK(outward_sum == 0.0);
    }
  }
}

TEST_CASE("contour motion: a section that does not change does not move; empty neighbours", "[unit][contour_motion]") {
  const auto p = PanelSymmetricSection(SemicircleContour(0.4), 10);
  const std::vector<std::vector<Panel>> fixed(3, p);
  const ContourMotion m = StepContourMotion(fixed, 1, 0.1);
  for (double w : m.normal_speed_m_s) CHECK(w == 0.0);
  for (const auto& w : m.waterline) CHECK(w.speed_m_s == 0.0);
  // Alone between empty steps: no neighbour to difference against.
  const std::vector<std::vector<Panel>> alone = {{}, p, {}};
  const ContourMotion a = StepContourMotion(alone, 1, 0.1);
  for (double w : a.normal_speed_m_s) CHECK(w == 0.0);
  CHECK_THROWS_AS(StepContourMotion(alone, 3, 0.1), std::out_of_range);
  CHECK_THROWS_AS(StepContourMotion(alone, 1, 0.0), std::invalid_argument);
}

TEST_CASE("waterline points of two bodies in a strip", "[unit][contour_motion]") {
  auto a = PanelSymmetricSection(SemicircleContour(0.3), 8, -1.0);
  const auto b = PanelSymmetricSection(SemicircleContour(0.3), 8, 1.0);
  a.insert(a.end(), b.begin(), b.end());
  const auto w = FindWaterlinePoints(a, 1e-9);
  REQUIRE(w.size() == 4);
  int towards_plus = 0;
  for (const auto& p : w) {
    const double centre = p.y_m < 0 ? -1.0 : 1.0;
    CHECK(p.outward == ((p.y_m > centre) ? 1.0 : -1.0));
    towards_plus += p.outward > 0;
  }
  CHECK(towards_plus == 2);
}
