// Impulsive (φ = 0 on the free surface) strip kernel: the infinite-frequency heave added mass of a semicircle
// (ρπR²/2, exact; second-order panel convergence) and of a catamaran pair far apart (twice one hull's).
#include <catch2/catch.hpp>
#include <cmath>

#include "seakeeping/strip/impulsive_strip_kernel.h"
#include "seakeeping/sections/section_shapes.h"

namespace sk = hullopt::sk;

namespace {
double HeaveAddedMass(const std::vector<sk::Panel>& ps, double rho) {
  const auto q = sk::ImpulsivePotentialIntegral(ps);
  double a = 0.0;
  for (std::size_t i = 0; i < ps.size(); ++i) a -= rho * q[i] * ps[i].Normal()[1];
  return a;
}
}  // namespace

TEST_CASE("impulsive heave added mass of a semicircle", "[impulsive]") {
  const double R = 1.0, rho = 1025.0;
  // Flat constant-strength panels with the curvature term of their self influence (rankine_panel.h) converge
  // at second order (without it first order: 3.1%, 1.6%, 0.8%, 0.4% at 32, 64, 128, 256 panels). Check the
  // order, then the value.
  const double exact = rho * M_PI * R * R / 2;
  const double e64 =
      HeaveAddedMass(sk::PanelSymmetricSection(sk::SemicircleContour(R, 4000), 64), rho) - exact;
  const double e256 =
      HeaveAddedMass(sk::PanelSymmetricSection(sk::SemicircleContour(R, 4000), 256), rho) - exact;
  INFO("errors " << e64 / exact << " at 64 panels, " << e256 / exact << " at 256");
  CHECK(e64 / e256 > 10.0);  // second order: 4× the panels, a sixteenth of the error (first order: 4)
  constexpr double kPanelTol = 1e-3;  // 64 panels: 0.04% by the second-order estimate
  CHECK(std::fabs(e64) < kPanelTol * exact);
  // Two far-apart semicircles: interaction decays like (R/d)², 1e-3 at d = 30 R.
  auto two = sk::PanelSymmetricSection(sk::SemicircleContour(R, 4000), 64, 30.0);
  const auto other = sk::PanelSymmetricSection(sk::SemicircleContour(R, 4000), 64, -30.0);
  two.insert(two.end(), other.begin(), other.end());
  const double one64 = exact + e64;
  CHECK(HeaveAddedMass(two, rho) == Approx(2 * one64).epsilon(2e-3));
}
