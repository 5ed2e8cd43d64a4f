// Strip geometry from a HullForm: stations, panels, beams against the hull's own hydrostatics; refusal of
// sections that do not reach the waterline; combining independent kernels.
#include <catch2/catch.hpp>
#include <cmath>

#include "parametric_hull/hydrostatics.h"
#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/strip/impulsive_strip_kernel.h"
#include "seakeeping/motions/periodic_motion_solver.h"
#include "seakeeping/motions/rao_solver.h"
#include "seakeeping/strip/strip_geometry.h"
#include "support/box_strip_kernel.h"

namespace sk = hullopt::sk;
namespace hull = hullopt::hull;

namespace {
// Box demihull, L × B × T with freeboard, stations every L/10.
hull::Demihull BoxBody(double L, double B, double T, double y_centre, double deck) {
  hull::Demihull b;
  b.role = y_centre > 0 ? "demihull" : "main";
  b.y_centre_m = y_centre;
  for (int i = 0; i <= 10; ++i) b.stations.push_back({L * i / 10.0, {0.0, B / 2, B / 2}, {0.0, 0.0, deck}});
  return b;
}
// Box monohull 10 × 1 × 0.5 m with 0.5 m freeboard.
hull::HullForm BoxMonohull() {
  hull::HullForm h;
  h.type = "monohull";
  h.draught_m = 0.5;
  h.length_m = 10;
  h.bodies.push_back(BoxBody(10, 1, 0.5, 0.0, 1.0));
  return h;
}
}  // namespace

TEST_CASE("strip geometry of a catamaran box: stations, panels and waterplane", "[strip_geometry]") {
  const double L = 10, B = 1, T = 0.5;
  hull::HullForm h;
  h.type = "catamaran";
  h.draught_m = T;
  h.length_m = L;
  h.bodies.push_back(BoxBody(L, B, T, 2.0, 1.0));
  sk::StripGeometryOptions o;
  o.sections = 20;
  o.panels = 10;
  o.layout = sk::StationLayout::kCellMidpoints;
  const auto k = sk::StripKernelGeometry(h, o, 5.0, 1025.0, 9.81);
  REQUIRE(k.Steps() == 20);
  CHECK(k.dx_m == Approx(0.5));
  CHECK(k.dt_s == Approx(0.1));
  CHECK(k.x_m.front() == Approx(L - 0.25));  // bow first, strip midpoints
  CHECK(k.x_m.back() == Approx(0.25));
  for (const auto& ps : k.panels) CHECK(ps.size() == 20u);  // both demihulls
  // Σ ρ g B Δx is the waterplane stiffness ρ g A_wp of the hull's own hydrostatics (independent quadrature).
  hull::MassProperties mass{2 * 1025.0 * L * B * T, L / 2, L / 4, 0.0};
  const sk::HeadSeaShipModel model(k, mass, sk::MotionOptions{});
  double awp = 0.0;
  for (const auto& s : model.stations()) {
    awp += s.beam_m * k.dx_m;
    CHECK(s.FroudeKrylovWidth(0.0) == Approx(s.beam_m).epsilon(1e-12));  // G(0) = B by definition
  }
  const auto hs = hull::ComputeHydrostatics(h, 1025.0);
  CHECK(awp == Approx(hs.awp_m2).epsilon(1e-12));
  // One demihull alone: half the panels and half the waterplane.
  o.body = 0;
  const auto k1 = sk::StripKernelGeometry(h, o, 5.0, 1025.0, 9.81);
  CHECK(k1.panels[3].size() == 10u);
}

TEST_CASE("strip geometry at the cell faces: stations, weights and waterplane", "[strip_geometry]") {
  const double L = 10, B = 1, T = 0.5;
  hull::HullForm h;
  h.type = "monohull";
  h.draught_m = T;
  h.length_m = L;
  h.bodies.push_back(BoxBody(L, B, T, 0.0, 1.0));
  sk::StripGeometryOptions o;
  o.sections = 20;
  o.panels = 10;
  o.layout = sk::StationLayout::kCellFaces;
  const auto k = sk::StripKernelGeometry(h, o, 5.0, 1025.0, 9.81);
  REQUIRE(k.Steps() == 21);
  CHECK(k.x_m.front() == L);   // bow face
  CHECK(k.x_m.back() == 0.0);  // transom face, the hull's own end station
  CHECK(k.Weight(0) == Approx(0.25));
  CHECK(k.Weight(10) == Approx(0.5));
  CHECK(k.Weight(20) == Approx(0.25));
  const hull::MassProperties mass{1025.0 * L * B * T, L / 2, L / 4, 0.0};
  const sk::HeadSeaShipModel model(k, mass, sk::MotionOptions{});
  double awp = 0.0;
  for (const auto& s : model.stations()) awp += s.beam_m * s.weight_m;
  CHECK(awp == Approx(hull::ComputeHydrostatics(h, 1025.0).awp_m2).epsilon(1e-12));
  o.sections = 2;
  CHECK_THROWS_WITH(sk::StripKernelGeometry(h, o, 5.0, 1025.0, 9.81), Catch::Contains("sections = 2"));
}

TEST_CASE("face-layout force stencil: the hull sum telescopes to the transom and is second order",
          "[strip_geometry][stencil]") {
  // For every momentum I_k of a strip, the weighted columns of the force rows w_n c_{n,k} (f_n = Σ c I / 2dt)
  // must give: Σ_n = 2·δ_{k,last} (momentum leaves only at the transom), Σ_n (n − k) = −2 q_k with q a
  // quadrature of ∫I dx in units of dx whose sum is the hull length, and Σ_n (n − k)² = 0 away from the
  // ends. Exact rational arithmetic in doubles: tolerance at round-off.
  constexpr double kExact = 1e-12;
  for (int sections : {3, 4, 7, 40}) {
    const int S = sk::StationCount(sk::StationLayout::kCellFaces, sections);
    double q_sum = 0.0;
    for (int k = 0; k < S; ++k) {
      double m0 = 0, m1 = 0, m2 = 0;
      for (int n = k; n < S && n <= k + 2; ++n) {
        const double wc = sk::StationWeight(sk::StationLayout::kCellFaces, n, S, 1.0) *
                          sk::StripForceStencil(sk::StationLayout::kCellFaces, n, S)[n - k];
        m0 += wc, m1 += wc * (n - k), m2 += wc * (n - k) * (n - k);
      }
      INFO("sections " << sections << " column " << k);
      CHECK(std::fabs(m0 - (k == S - 1 ? 2.0 : 0.0)) < kExact);
      q_sum += -0.5 * m1;
      if (k == 0) CHECK(std::fabs(-0.5 * m1 - 0.5) < kExact);  // trapezoid weight at the bow face
      if (k < S - 2) CHECK(std::fabs(m2) < kExact);
    }
    CHECK(std::fabs(q_sum - sections) < kExact);
  }
}

TEST_CASE("zero kernel on a real geometry: static limit", "[strip_geometry][limits]") {
  const hull::HullForm h = BoxMonohull();
  sk::StripGeometryOptions o;
  const auto k = sk::StripKernelGeometry(h, o, 7.9, 1025.0, 9.81);
  hull::MassProperties mass{1025.0 * 10 * 1 * 0.5, 5.0, 2.5, 0.0};
  sk::MotionOptions mo;
  mo.damping_cs = 0.05;
  const sk::HeadSeaShipModel model(k, mass, mo);
  const auto r = sk::SolvePeriodicRaos(model, {0.02});
  constexpr double kStaticTol = 5e-3;  // O(kL) corrections at kL = 4e-4, plus cosine-panel corner cutting
  CHECK(std::abs(r.heave[0] - 1.0) < kStaticTol);
  CHECK(std::abs(r.pitch[0] - std::complex<double>(0, -1)) < kStaticTol);
}

TEST_CASE("a section that does not reach the waterline is refused", "[strip_geometry][errors]") {
  hull::HullForm h;
  h.type = "monohull";
  h.draught_m = 0.5;
  h.bodies.push_back(BoxBody(10, 1, 0.5, 0.0, 0.4));  // deck edge at 0.4 m, below the 0.5 m draught
  sk::StripGeometryOptions o;
  CHECK_THROWS_WITH(sk::StripKernelGeometry(h, o, 5.0, 1025.0, 9.81),
                    Catch::Contains("does not reach the waterline") && Catch::Contains("x ="));
  h.bodies[0] = BoxBody(10, 1, 0.5, 0.0, 1.0);
  CHECK_THROWS_WITH(sk::StripKernelGeometry(h, o, 0.0, 1025.0, 9.81), Catch::Contains("speed"));
  o.panels = 7;
  CHECK_THROWS_WITH(sk::StripKernelGeometry(h, o, 5.0, 1025.0, 9.81), Catch::Contains("panels = 7"));
}

TEST_CASE("independent kernels combine to the sum of their forces", "[strip_geometry]") {
  hullopt::testing::BoxHull b;
  b.sections = 30;
  const auto one = hullopt::testing::BoxKernel(b, 400.0);
  const auto two = sk::CombineIndependentKernels({one, one});
  CHECK(two.panels[5].size() == 2 * one.panels[5].size());
  // Two identical hulls side by side without interaction, twice the mass and inertia: the same RAOs.
  hull::MassProperties m1{1025.0 * b.L * b.B * b.T, b.L / 2, b.L / 4, 0.0}, m2 = m1;
  m2.mass_kg *= 2;
  sk::MotionOptions mo;
  mo.damping_cs = 0.1;
  const sk::HeadSeaShipModel a(one, m1, mo), c(two, m2, mo);
  const std::vector<double> w = {1.0, 1.5, 2.0};
  const auto ra = sk::SolvePeriodicRaos(a, w), rc = sk::SolvePeriodicRaos(c, w);
  for (std::size_t i = 0; i < w.size(); ++i) {
    CHECK(std::abs(ra.heave[i] - rc.heave[i]) < 1e-12 * std::abs(ra.heave[i]) + 1e-14);
    CHECK(std::abs(ra.pitch[i] - rc.pitch[i]) < 1e-12 * std::abs(ra.pitch[i]) + 1e-14);
  }
}

TEST_CASE("demihulls far apart: with and without interaction agree", "[strip_geometry][interaction]") {
  hull::HullForm h;
  h.type = "catamaran";
  h.draught_m = 0.5;
  h.length_m = 10;
  h.bodies.push_back(BoxBody(10, 1, 0.5, 200.0, 1.0));  // 400 m apart: interaction ~ (B/d)² ≈ 1e-5
  sk::RaoSolverOptions o;
  o.sections = 20;
  o.panels = 8;
  o.motion.damping_cs = 0.05;
  const hull::MassProperties mass{2 * 1025.0 * 10 * 1 * 0.5, 5.0, 2.5, 0.0};
  const std::vector<double> w = {1.0, 2.0, 3.0};
  const auto with = sk::ComputeRaos(h, mass, 7.9, 1025.0, 9.81, w, o, sk::FillImpulsiveStripKernel);
  o.interaction = false;
  const auto without = sk::ComputeRaos(h, mass, 7.9, 1025.0, 9.81, w, o, sk::FillImpulsiveStripKernel);
  constexpr double kFarTol = 1e-3;
  for (std::size_t i = 0; i < w.size(); ++i) {
    CHECK(std::abs(with.heave[i] - without.heave[i]) < kFarTol * std::abs(with.heave[i]));
    CHECK(std::abs(with.pitch[i] - without.pitch[i]) < kFarTol * std::abs(with.pitch[i]));
  }
}

TEST_CASE("strip geometry: the panel spacing option reaches the sections", "[strip_geometry]") {
  // A smaller end_spacing gives a shorter waterline panel (the panels share ∫ ds/h equally and h is smallest at
  // the waterline and the corners; with the count fixed, only the order is certain, not the ratio).
  const hull::HullForm h = BoxMonohull();
  sk::StripGeometryOptions o;
  o.sections = 10;
  o.panels = 14;
  const auto a = sk::StripKernelGeometry(h, o, 5.0, 1025.0, 9.81);
  o.spacing.end_spacing = 0.08;
  const auto b = sk::StripKernelGeometry(h, o, 5.0, 1025.0, 9.81);
  const auto& pa = a.panels[5], &pb = b.panels[5];
  REQUIRE(pa.size() == 14);
  REQUIRE(pb.size() == 14);
  CHECK(pb.front().Length() < pa.front().Length());
  CHECK(pb.front().z1 == 0.0);  // still ending at the waterline
  o.spacing.end_spacing = 0.0;
  std::string err;
  CHECK_FALSE(o.IsValid(&err));
  CHECK(err.find("end_spacing") != std::string::npos);
}
