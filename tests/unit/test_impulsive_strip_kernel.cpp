// Impulsive (φ = 0 on the free surface) strip kernel: the infinite-frequency heave added mass of a semicircle
// (ρπR²/2, exact) and of a catamaran pair far apart (twice one hull's).
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
  // Constant-strength panels converge only as 1/n here: where the body meets the φ = 0 surface the potential
  // has a corner (errors 3.1%, 1.6%, 0.8%, 0.4% at 32, 64, 128, 256 panels). Check the order, then the value.
  const double exact = rho * M_PI * R * R / 2;
  const double e64 =
      HeaveAddedMass(sk::PanelSymmetricSection(sk::SemicircleContour(R, 4000), 64), rho) - exact;
  const double e256 =
      HeaveAddedMass(sk::PanelSymmetricSection(sk::SemicircleContour(R, 4000), 256), rho) - exact;
  CHECK(e64 / e256 == Approx(4.0).epsilon(0.1));  // first order: 4× the panels, a quarter of the error
  constexpr double kPanelTol = 6e-3;              // 256 panels: 0.4% by the first-order estimate
  CHECK(std::fabs(e256) < kPanelTol * exact);
  // Two far-apart semicircles: interaction decays like (R/d)², 1e-3 at d = 30 R.
  auto two = sk::PanelSymmetricSection(sk::SemicircleContour(R, 4000), 64, 30.0);
  const auto other = sk::PanelSymmetricSection(sk::SemicircleContour(R, 4000), 64, -30.0);
  two.insert(two.end(), other.begin(), other.end());
  const double one64 = exact + e64;
  CHECK(HeaveAddedMass(two, rho) == Approx(2 * one64).epsilon(2e-3));
}
