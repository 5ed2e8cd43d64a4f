// The strips' power and the 2D+t wave resistance (seakeeping/strip/strip_power.h, calm_water.h):
// - the march's potential, evaluated point by point from closed-form panel integrals, gives the strip momentum
//   ρ∫φ n_z dl that the operators' batched tables give (two independent evaluations of the same potential);
// - in the φ = 0 limit of the free surface (g → 0) no energy is left in the water once a closed hull has
//   passed, so the work of the strips' pressure, the wave resistance, vanishes (d'Alembert in 2D+t); the
//   discretised value falls towards 0 as the sections are refined;
// - at finite g the water keeps the energy of the waves the hull made: R > 0.
#include <catch2/catch.hpp>
#include <cmath>

#include "seakeeping/green/gauss_legendre.h"
#include "seakeeping/motions/calm_water.h"
#include "seakeeping/motions/instantaneous_sections.h"
#include "seakeeping/strip/contour_motion.h"
#include "seakeeping/strip/strip_marcher.h"
#include "seakeeping/strip/strip_power.h"
#include "support/semicircle_hull.h"

namespace sk = hullopt::sk;
namespace hull = hullopt::hull;

namespace {
constexpr double kL = 3.0, kR0 = 0.12, kT = 0.2, kRho = 1000.0;
const hullopt::test::SemicircleHullShape kShape{kL, kR0, kT};

// A closed slender hull: semicircles of radius R0·4s(1 − s), s = x/L, down to 2 % of R0 at the ends (an end
// area of 4e-4 of the midship's).
hull::HullForm ClosedHull() {
  return hullopt::test::SemicircleHullOf(kShape, [](double x) {
    const double s = x / kL;
    return kR0 * std::fmax(0.02, 4.0 * s * (1.0 - s));
  });
}

hull::MassProperties Mass() {
  hull::MassProperties m;
  m.mass_kg = 100.0, m.lcg_m_from_ap = 0.5 * kL, m.kyy_m = 0.25 * kL, m.kg_m = kT;
  return m;
}

sk::SteadyForce Resistance(const hull::HullForm& h, double U, double g, int sections, int panels = 14) {
  sk::CalmWaterOptions o;
  o.geometry.sections = sections;
  o.geometry.panels = panels;
  o.wave_resistance = true;
  return sk::CalmWaterForce(h, Mass(), hull::RunningAttitude{}, U, kRho, g, o);
}
}  // namespace

TEST_CASE("the march's potential point by point gives the operators' strip momentum", "[verification][strip_power]") {
  const hull::HullForm h = hullopt::test::SemicircleHull(kShape, hullopt::test::Taper::kAft);
  sk::StripGeometryOptions geo;
  geo.sections = 20;
  geo.panels = 14;
  const sk::CellFaceStations grid = sk::CellFaceGrid(h, geo.sections);
  const int steps = geo.sections + 1;
  const double U = 4.07, dt = grid.dx_m / U;
  std::vector<std::vector<sk::Panel>> panels(steps), contours(steps);
  for (int n = 0; n < steps; ++n) panels[n] = sk::StripSectionPanels(h, grid.x_m[n], h.draught_m, geo, &contours[n]);
  std::vector<sk::ContourMotion> motions(steps);
  for (int n = 0; n < steps; ++n) motions[n] = sk::StepContourMotion(panels, n, dt, &contours);
  sk::StripOperatorOptions oo;
  oo.layout = sk::StationLayout::kCellFaces;
  oo.use_mirror_symmetry = true;
  const sk::StripOperators ops = sk::BuildStripOperators(panels, dt, kRho, 9.81, oo, &motions);
  sk::StripMarcher marcher(ops);
  for (int n = 0; n < steps; ++n) {
    Eigen::VectorXd vn = Eigen::VectorXd::Zero(ops.PanelCount(n));
    for (std::size_t p = 0; p < ops.ReducedIndex(n).size(); ++p)
      vn(ops.ReducedIndex(n)[p]) += ops.ReducedShare(n)[p] * motions[n].normal_speed_m_s[p];
    marcher.Advance(vn);
  }
  const auto& rule = sk::GaussLegendre01(oo.field_points_per_panel);
  double largest = 0.0, worst = 0.0;
  for (int n = 0; n < steps; ++n) {
    std::vector<double> y, z, w;
    for (const sk::Panel& p : ops.FullPanelsAt(n))
      for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
        y.push_back(p.y1 + rule.nodes[q] * (p.y2 - p.y1));
        z.push_back(p.z1 + rule.nodes[q] * (p.z2 - p.z1));
        w.push_back(rule.weights[q] * p.Length() * p.Normal()[1]);
      }
    if (y.empty()) continue;
    const std::vector<double> phi = sk::MarchPotential(ops, marcher.Sources(), n, y, z);
    double I = 0.0;
    for (std::size_t i = 0; i < phi.size(); ++i) I += kRho * w[i] * phi[i];
    largest = std::fmax(largest, std::fabs(marcher.Momentum()[n]));
    worst = std::fmax(worst, std::fabs(I - marcher.Momentum()[n]));
  }
  INFO("largest |I| " << largest << " kg/s, largest difference " << worst);
  REQUIRE(largest > 0.0);
  // Both are the same potential at the same Gauss points; the operators take the memory from tables of the
  // Dawson integral (a few units in the 13th digit, transient_green.h), the point-by-point path from the same
  // kernel function one point at a time: agreement to round-off of the memory sums.
  CHECK(worst <= 1e-9 * largest);
}

TEST_CASE("2D+t wave resistance: zero at g -> 0 for a closed hull, positive at finite g", "[verification][strip_power]") {
  const hull::HullForm h = ClosedHull();
  const double U = 4.07;
  SECTION("g -> 0: the work of the pressure vanishes to a small floor") {
    // φ = 0 on the free surface in the limit (as test_calm_water_closed_forms.cpp: g = 0.01 m/s²). The hull is
    // fore-and-aft symmetric, so the quadratic pressure the linear strips leave out does no net work either:
    // the linear pressure's work must vanish too.
    for (int sections : {20, 40, 80}) {
      const sk::SteadyForce f = Resistance(h, U, 0.01, sections);
      double work = 0.0;  // Σ |P_n| w_n / U: the size of the terms that must cancel
      const sk::CellFaceStations grid = sk::CellFaceGrid(h, sections);
      for (std::size_t n = 0; n < f.power_W_per_m.size(); ++n) work += std::fabs(f.power_W_per_m[n]) * grid.weight_m[n] / U;
      const double ratio = std::fabs(f.wave_resistance_N) / work;
      INFO(sections << " sections: R = " << f.wave_resistance_N << " N against the cancelling terms' " << work
                    << " N (ratio " << ratio << ")");
      REQUIRE(work > 0.0);
      // Measured: 2.0 % at 20 sections, then a floor of 0.2-0.4 % (0.03 N; 160 x 28 gives the same) whose source
      // is not identified: 0.3 % of the resistance at Fn 0.75 below. A sign error or a difference taken on the
      // body's inside would leave tens of percent.
      CHECK(ratio < (sections == 20 ? 0.025 : 0.005));
    }
  }
  SECTION("finite g: positive, the energy of the waves left behind") {
    for (double Fn : {0.5, 0.75, 1.0}) {
      const double Ug = Fn * std::sqrt(9.81 * kL);
      const sk::SteadyForce f = Resistance(h, Ug, 9.81, 40);
      INFO("Fn " << Fn << ": R = " << f.wave_resistance_N << " N");
      CHECK(f.wave_resistance_N > 0.0);
    }
  }
}
