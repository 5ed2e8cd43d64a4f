// The oblique periodic solver (seakeeping/motions/oblique_periodic_solver.h) against the head-sea periodic
// path and the symmetries of a port–starboard symmetric hull:
//  - the strip kernel's lateral rows leave its vertical rows bitwise as they are without them;
//  - at β = 180° heave and pitch equal the head-sea periodic path's (periodic_motion_solver.h) on the same
//    kernel, Cs damping included: the same strip sums assembled independently and solved by a 5 × 5 LU
//    instead of the 2 × 2 Cramer rule;
//  - sway, roll and yaw vanish at β = 180° and β = 0° (to round-off), and are not zero in oblique seas;
//  - an encounter frequency <= 0 (following seas at speed) is refused, as the oblique strip theory refuses
//  it.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <cstdio>
#include <stdexcept>

#include "seakeeping/motions/periodic_motion_solver.h"
#include "seakeeping/strip/strip_kernel_builder.h"
#include "support/oblique_periodic_case.h"
#include "support/wigley_hull.h"
#include "support/wigley_oblique.h"

using namespace hullopt;

namespace {
constexpr double kRho = 1000.0, kG = 9.81;

hull::MassProperties WigleyMass() {
  hull::MassProperties m;
  m.mass_kg = 75.0;  // the displaced mass of data/peers-oblique/ (a strip hull's own volume differs slightly)
  m.lcg_m_from_ap = 0.5 * test::kWigleyL;
  m.kyy_m = 0.25 * test::kWigleyL;
  m.kg_m = 0.15;
  return m;
}

sk::ObliquePeriodicOptions Options(const hull::MassProperties& m) {
  sk::ObliquePeriodicOptions o;
  o.mass = test::WigleyObliqueMass(m.kg_m);
  return o;
}

double Fraction(const sk::ObliqueWaveResult& w) {
  // Sway, roll and yaw RAOs against heave's and pitch's.
  const double scale = std::abs(w.rao[2]) + std::abs(w.rao[4]);
  return (std::abs(w.rao[1]) + std::abs(w.rao[3]) + std::abs(w.rao[5])) / scale;
}
}  // namespace

TEST_CASE("lateral rows leave the vertical rows of the strip kernel bitwise unchanged",
          "[verification][oblique]") {
  const hull::HullForm hull = test::WigleyHull(test::kWigleyL, test::kWigleyB, test::kWigleyT, 101, 31);
  sk::StripGeometryOptions go;
  go.sections = 12;
  go.panels = 8;
  const sk::StripKernel geo = sk::StripKernelGeometry(hull, go, 1.0, kRho, kG);
  sk::StripOperatorOptions plain, lateral;
  plain.layout = lateral.layout = geo.layout;
  lateral.lateral_rows = true;
  const sk::StripKernel a = sk::BuildStripKernel(geo.panels, geo.x_m, geo.dt_s, kRho, kG, plain);
  const sk::StripKernel b = sk::BuildStripKernel(geo.panels, geo.x_m, geo.dt_s, kRho, kG, lateral);
  REQUIRE(a.lateral_force.empty());
  REQUIRE(b.lateral_force.size() == b.force.size());
  for (int n = 0; n < a.Steps(); ++n)
    for (int m = 0; m <= n; ++m) {
      REQUIRE(b.lateral_force[n][m].rows() == 2);
      REQUIRE(b.lateral_force[n][m].cols() == a.force[n][m].cols());
      REQUIRE((a.force[n][m].array() == b.force[n][m].array()).all());
    }
  // Lateral rows need full sections and the momentum form.
  sk::StripOperatorOptions bad = lateral;
  bad.use_mirror_symmetry = true;
  CHECK_FALSE(bad.IsValid(nullptr));
  bad = lateral;
  bad.sectional_force = sk::SectionalForce::kPressure;
  CHECK_FALSE(bad.IsValid(nullptr));
}

TEST_CASE("oblique periodic solver at 180 deg: the head-sea periodic path's heave and pitch",
          "[verification][oblique]") {
  // Round-off: the same kernel rows and strip sums, assembled in a different order (three rows per pair,
  // generalised forces) and solved by a 5 × 5 LU through A and B instead of the 2 × 2 Cramer rule; relative
  // differences seen are 6e-15, the tolerance leaves room for the conditioning near the heave-pitch
  // resonance.
  constexpr double kRoundOff = 1e-9;
  // Sway, roll and yaw of a symmetric hull in head and following seas: the lateral rows' response to the
  // symmetric inputs of mirror-symmetric panels, zero but for round-off (measured 2e-11 of the heave and
  // pitch RAOs).
  constexpr double kSymmetric = 1e-9;
  // The encounter frequency: the same formula ω + ω²U/g written two ways (a few ulps).
  constexpr double kFormula = 1e-15;
  // Oblique seas (135°) must excite sway, roll and yaw clearly: their share of the motion is O(0.1–1) on this
  // hull, so a thousandth separates "excited" from the round-off above by six orders.
  constexpr double kExcited = 1e-3;
  const hull::HullForm hull = test::WigleyHull(test::kWigleyL, test::kWigleyB, test::kWigleyT, 101, 31);
  const hull::MassProperties mass = WigleyMass();
  const double U = 0.2 * std::sqrt(kG * test::kWigleyL);  // Fn 0.2
  const auto c = test::MakeObliquePeriodicCase(hull, mass, U, 16, 10, 0.1);
  std::vector<double> omega;
  for (double w = 2.0; w <= 9.0; w += 0.5) omega.push_back(w);
  const sk::RaoTable head = sk::SolvePeriodicRaos(*c.model, omega);
  const sk::ObliqueStripResult r =
      sk::SolveObliquePeriodic(*c.model, omega, {180.0, 0.0, 135.0}, Options(mass));
  REQUIRE(r.waves.size() == 3 * omega.size());
  double worst = 0.0, worst_symmetric = 0.0;
  for (std::size_t f = 0; f < omega.size(); ++f) {
    worst = std::max({worst, std::abs(r.Wave(0, f).rao[2] - head.heave[f]) / std::abs(head.heave[f]),
                      std::abs(r.Wave(0, f).rao[4] - head.pitch[f]) / std::abs(head.pitch[f])});
    worst_symmetric = std::max({worst_symmetric, Fraction(r.Wave(0, f)), Fraction(r.Wave(1, f))});
  }
  std::printf(
      "180 deg against the head-sea path: largest relative difference %.2e; sway, roll and yaw share at "
      "180 and 0 deg %.2e\n",
      worst, worst_symmetric);
  for (std::size_t f = 0; f < omega.size(); ++f) {
    const sk::ObliqueWaveResult& w = r.Wave(0, f);
    INFO("omega = " << omega[f]);
    CHECK(w.omega_e_rad_s == Approx(head.omega_e_rad_s[f]).epsilon(kFormula));
    CHECK(std::abs(w.rao[2] - head.heave[f]) <= kRoundOff * std::abs(head.heave[f]));
    CHECK(std::abs(w.rao[4] - head.pitch[f]) <= kRoundOff * std::abs(head.pitch[f]));
    CHECK(Fraction(w) <= kSymmetric);
    if (r.Wave(1, f).omega_e_rad_s > 0.0) CHECK(Fraction(r.Wave(1, f)) <= kSymmetric);
    // Oblique seas excite the antisymmetric modes (a clearly non-zero share of the motion).
    CHECK(Fraction(r.Wave(2, f)) > kExcited);
  }
  // Following seas at speed with ω_e <= 0 (ω >= g/U = 9.0 rad/s at this speed) are refused.
  CHECK_THROWS_AS(sk::SolveObliquePeriodic(*c.model, {10.0}, {0.0}, Options(mass)), std::domain_error);
  CHECK_THROWS_AS(sk::SolveObliquePeriodic(*c.model, {2.0}, {}, Options(mass)), std::invalid_argument);
}

TEST_CASE("oblique periodic solver needs the lateral rows", "[verification][oblique]") {
  const hull::HullForm hull = test::WigleyHull(test::kWigleyL, test::kWigleyB, test::kWigleyT, 101, 31);
  sk::RaoSolverOptions o;
  o.sections = 8;
  o.panels = 6;
  const sk::StripKernel k =
      sk::BuildHullStripKernel(hull, o, 1.0, kRho, kG, sk::TransientGreenKernelBuilder());
  const sk::HeadSeaShipModel model(k, WigleyMass(), {});
  CHECK_THROWS_AS(sk::SolveObliquePeriodic(model, {3.0}, {90.0}, Options(WigleyMass())),
                  std::invalid_argument);
}
