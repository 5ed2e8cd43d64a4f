// Near-singular strip sections are reported (seakeeping/strip_kernel.h, StripKernelWarnings). Independent
// facts used: a semicircle or a box of moderate proportions is a well-posed Neumann problem for constant
// source panels (condition estimate of order 1–10); a submerged plate thinner than its panels are long (a
// strut over a flat "bulb", like the generator's SWATH bow sections) puts panels of opposite normals within a
// fraction of their length of each other, so the source system approaches the singular one of a zero-thickness
// plate; the estimate must grow without bound as the plate thins at fixed panel count.
#include <catch2/catch.hpp>

#include "seakeeping/sections/section_shapes.h"
#include "seakeeping/strip/strip_kernel.h"
#include "seakeeping/strip/strip_kernel_builder.h"
#include "seakeeping/strip/strip_operators.h"

using namespace hullopt::sk;

namespace {
double Condition(const std::vector<Panel>& section) {
  // Four identical steps (the cell-face layout's minimum); step 1 carries the self-memory term.
  const auto ops = BuildStripOperators({section, section, section, section}, 0.05, 1025.0, 9.81);
  return ops.ConditionEstimate(1);
}
}  // namespace

TEST_CASE("well-posed sections are well conditioned, a flattening box is not", "[td][conditioning]") {
  const double semicircle = Condition(PanelSymmetricSection(SemicircleContour(1.0), 14));
  const double box = Condition(PanelSymmetricSection(RectangleContour(2.0, 1.0), 14));
  INFO("semicircle " << semicircle << ", box B/T 2 " << box);
  CHECK(semicircle < 10.0);
  CHECK(box < 10.0);
  // Half contour keel → waterline: plate bottom out to y = 2 m at z = −1 m, up its edge by e, back along its
  // top to the strut (half breadth 0.3 m) and up the strut to the waterline. Panels about 0.45 m long.
  auto strut_and_plate = [](double e) {
    return HalfContour{{0.0, -1.0}, {2.0, -1.0}, {2.0, -1.0 + e}, {0.3, -1.0 + e}, {0.3, 0.0}};
  };
  // Panels placed on both faces however thin the plate (cut_thickness_fraction = 0): the fact itself.
  PanelSpacing resolve_all;
  resolve_all.cut_thickness_fraction = 0.0;
  double previous = 0.0;
  for (double e : {0.3, 0.03, 0.003}) {
    const double c = Condition(PanelSymmetricSection(strut_and_plate(e), 14, 0.0, resolve_all));
    INFO("strut over a plate " << e << " m thick: " << c);
    CHECK(c > previous);
    previous = c;
  }
  CHECK(previous > kIllConditionedStrip);
  // The default panelling cuts a plate too thin for the panel count at its root (seakeeping/green/panel.h)
  // and stays well conditioned for any thickness.
  for (double e : {0.3, 0.03, 0.003, 0.0003}) {
    const double c = Condition(PanelSymmetricSection(strut_and_plate(e), 14));
    INFO("default panelling, strut over a plate " << e << " m thick: " << c);
    CHECK(c < kIllConditionedStrip);
  }
}

TEST_CASE("StripKernelWarnings names the worst station and the limit", "[td][conditioning]") {
  StripKernel k;
  k.x_m = {3.0, 2.0, 1.0, 0.0};
  k.system_condition = {2.0, 350.0, 1200.0, 5.0};
  const auto w = StripKernelWarnings(k);
  REQUIRE(w.size() == 1);
  CHECK(w[0].find("2 of 4 strip sections") != std::string::npos);
  CHECK(w[0].find("above 200") != std::string::npos);
  CHECK(w[0].find("worst 1200 at x = 1 m") != std::string::npos);
  k.system_condition = {2.0, 3.0, 4.0, 5.0};
  CHECK(StripKernelWarnings(k).empty());
  k.system_condition.clear();  // a builder without estimates (impulsive stand-in): nothing to report
  CHECK(StripKernelWarnings(k).empty());
}
