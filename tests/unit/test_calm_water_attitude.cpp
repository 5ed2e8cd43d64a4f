// The running-attitude iteration of calm water (seakeeping/motions/calm_water.h): a converged attitude is an
// equilibrium, and an iteration that cannot converge says so instead of returning an attitude.
#include <catch2/catch.hpp>
#include <cmath>

#include "seakeeping/motions/calm_water.h"

namespace sk = hullopt::sk;
namespace hull = hullopt::hull;

namespace {
constexpr double kL = 3.0, kT = 0.15, kRho = 1000.0, kG = 9.81;

// A wall-sided hull of rectangular sections whose beam narrows linearly over the fore half (a fine bow) and
// whose deck is 0.15 m above the water line.
hull::HullForm BoxHull() {
  hull::Demihull b;
  b.role = "main";
  for (int i = 0; i <= 30; ++i) {
    const double x = kL * i / 30.0, half = x < 0.5 * kL ? 0.12 : 0.12 * (0.1 + 0.9 * (kL - x) / (0.5 * kL));
    b.stations.push_back(hull::Station{x, {0.0, half, half}, {0.0, 0.0, 2.0 * kT}});
  }
  hull::HullForm h;
  h.type = "monohull";
  h.draught_m = kT;
  h.length_m = kL;
  h.bodies = {b};
  return h;
}

hull::MassProperties Mass() {
  hull::MassProperties m;
  m.mass_kg = 80.0, m.lcg_m_from_ap = 1.3, m.kyy_m = 0.75, m.kg_m = kT;
  return m;
}

sk::CalmWaterOptions Options() {
  sk::CalmWaterOptions o;
  o.geometry.sections = 20;
  o.geometry.panels = 8;
  return o;
}
}  // namespace

TEST_CASE("a converged running attitude balances the steady force", "[unit][calm_water]") {
  const double U = 0.7 * std::sqrt(kG * kL);
  const sk::CalmWaterResult r = sk::SolveRunningAttitude(BoxHull(), Mass(), U, kRho, kG, Options());
  INFO(r.note);
  REQUIRE(r.converged);
  // Residuals against the hydrostatic stiffness: a force that would move the hull by less than the sinkage
  // tolerance (10 µm) and a moment worth less than the trim tolerance (0.001°).
  const double C33 = kRho * kG * 0.24 * kL;  // upper bound of ρ g A_wp
  CHECK(std::abs(r.force.heave_N) < C33 * 1e-5);
  CHECK(std::abs(r.force.moment_N_m) < C33 * kL * kL / 12.0 * (1e-3 * M_PI / 180.0));
  // The attitude the result reports is the one its force was computed at.
  const sk::SteadyForce f = sk::CalmWaterForce(BoxHull(), Mass(), r.attitude, U, kRho, kG, Options());
  CHECK(f.heave_N == r.force.heave_N);
  CHECK(f.moment_N_m == r.force.moment_N_m);
}

TEST_CASE("an attitude iteration that cannot converge reports why", "[unit][calm_water]") {
  const double U = 0.7 * std::sqrt(kG * kL);
  sk::CalmWaterOptions o = Options();
  o.max_iterations = 1;
  const sk::CalmWaterResult r = sk::SolveRunningAttitude(BoxHull(), Mass(), U, kRho, kG, o);
  CHECK_FALSE(r.converged);
  CHECK(r.note.find("did not converge in 1 iterations") != std::string::npos);
  // A deck a few millimetres above the water: the running trim submerges it, and the note names the rule.
  hull::HullForm low = BoxHull();
  for (auto& s : low.bodies[0].stations) s.z_m.back() = kT + 0.002;
  const sk::CalmWaterResult d = sk::SolveRunningAttitude(low, Mass(), U, kRho, kG, Options());
  CHECK_FALSE(d.converged);
  CHECK(d.note.find("left the hull's range") != std::string::npos);
}

TEST_CASE("calm-water options are checked", "[unit][calm_water]") {
  sk::CalmWaterOptions o = Options();
  std::string e;
  CHECK(o.IsValid(&e));
  o.max_iterations = 0;
  CHECK_FALSE(o.IsValid(&e));
  CHECK(e.find("max_iterations") != std::string::npos);
  o = Options();
  o.geometry.layout = sk::StationLayout::kCellMidpoints;
  CHECK_FALSE(o.IsValid(&e));
  CHECK_THROWS_AS(sk::CalmWaterForce(BoxHull(), Mass(), {}, 0.0, kRho, kG, Options()), std::invalid_argument);
}
