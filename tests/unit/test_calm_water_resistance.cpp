// Calm-water resistance pieces against closed forms: the ITTC-1957 line, the wetted surface of a box and of a
// wedge-ended wall-sided body, the dry-transom deficit of a box, the Michell amplitude of a wall-sided body
// (open transom, blunt bow), the viscosity rule and the sum R_T = (1+k) R_F + R_W + R_h.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>

#include "resistance/calm_water_resistance.h"
#include "resistance/friction_line.h"
#include "resistance/water_viscosity.h"
#include "resistance/wetted_surface.h"

using namespace hullopt;

namespace {
// Closed forms evaluated in a few operations; the polyline geometry is exact for these bodies.
constexpr double kRoundOff = 1e-10;

// Wall-sided body of length L, draught T, half-breadth b(x) linear from b_aft at x = 0 to b_fwd at L; the deck
// edge at 2 T b / b_aft, so the chine sits at the same arc fraction of every contour and the hull's ruled
// surface between stations is exactly the planes y = b(x) and z = 0.
hull::HullForm WallSided(double L, double T, double b_aft, double b_fwd, int stations) {
  hull::HullForm h;
  h.type = "monohull";
  h.draught_m = T;
  h.length_m = L;
  hull::Demihull body;
  body.role = "main";
  for (int i = 0; i < stations; ++i) {
    const double x = L * i / (stations - 1), b = b_aft + (b_fwd - b_aft) * x / L;
    body.stations.push_back(hull::Station{x, {0.0, b, b}, {0.0, 0.0, 2.0 * T * b / b_aft}});
  }
  h.bodies.push_back(body);
  return h;
}
}  // namespace

TEST_CASE("ITTC-1957 line at round Reynolds numbers", "[resistance]") {
  CHECK(res::Ittc1957FrictionCoefficient(1e7) == Approx(0.075 / 25.0).epsilon(kRoundOff));
  CHECK(res::Ittc1957FrictionCoefficient(1e9) == Approx(0.075 / 49.0).epsilon(kRoundOff));
  CHECK_THROWS_AS(res::Ittc1957FrictionCoefficient(50.0), std::invalid_argument);
}

TEST_CASE("viscosity follows the density: fresh below the threshold, sea water above", "[resistance]") {
  CHECK(res::ViscosityForDensity(1000.0) == res::kFreshWater15CViscosity);
  CHECK(res::ViscosityForDensity(1025.0) == res::kSeaWater15CViscosity);
}

TEST_CASE("wetted surface of a box and of a tapered wall-sided body", "[resistance]") {
  const double L = 10.0, T = 0.5;
  // box: 2 sides L T + bottom L B, B = 2 b
  CHECK(res::WettedSurface(WallSided(L, T, 0.4, 0.4, 11), 16) == Approx(L * (2 * T + 0.8)).epsilon(kRoundOff));
  // taper in plan, b from 0.4 to 0.2: sides 2 T L √(1 + (0.2/L)²), bottom ∫ 2 b dx = 0.6 L
  const double taper = 2.0 * T * L * std::sqrt(1.0 + 0.04 / (L * L)) + 0.6 * L;
  CHECK(res::WettedSurface(WallSided(L, T, 0.4, 0.2, 7), 16) == Approx(taper).epsilon(kRoundOff));
}

TEST_CASE("dry-transom deficit of a box: rho g B T^2 / 2", "[resistance]") {
  const double L = 10.0, T = 0.5, b = 0.4;
  const res::TransomGeometry t = res::ComputeTransomGeometry(WallSided(L, T, b, b, 11));
  CHECK(t.area_m2 == Approx(2 * b * T).epsilon(kRoundOff));
  CHECK(t.first_moment_m3 == Approx(2 * b * T * T / 2).epsilon(kRoundOff));
  CHECK(t.max_depth_m == Approx(T));
}

TEST_CASE("Michell amplitude of a box: only the bow step radiates (open transom)", "[resistance]") {
  // f = b on [0, L] x [0, T]: ∂f/∂x = -b δ(x - L) at the bow, none at the open transom, so
  // I(λ) = -b (1 - e^{-k0 λ² T}) / (k0 λ²) e^{i k0 λ L}. The grid is exact for f linear in x and d.
  const double L = 10.0, T = 0.5, b = 0.4, k0 = 9.81 / 25.0;
  const auto grids = res::SampleCentrePlanes(WallSided(L, T, b, b, 11), 6);
  for (double lam : {1.0, 1.3, 2.0, 5.0, 17.0}) {
    const double kz = k0 * lam * lam;
    const std::complex<double> exact = -b * (1.0 - std::exp(-kz * T)) / kz * std::polar(1.0, k0 * lam * L);
    const std::complex<double> got = res::AmplitudeFunction(grids[0], k0, lam);
    CHECK(std::abs(got - exact) < kRoundOff * std::abs(exact) + 1e-14);
  }
}

TEST_CASE("total resistance is the sum of its parts; speed zero is refused", "[resistance]") {
  res::ResistanceOptions o;
  o.form_factor = 1.2;
  const res::CalmWaterResistance model(WallSided(10.0, 0.5, 0.4, 0.1, 21), o);
  const res::ResistanceAtSpeed r = model.At(3.0, 1025.0, 9.81);
  CHECK(r.R_T_N == Approx(1.2 * r.R_F_N + r.R_W_N + r.R_H_N).epsilon(kRoundOff));
  CHECK(r.P_E_W == Approx(r.R_T_N * 3.0).epsilon(kRoundOff));
  const double q = 0.5 * 1025.0 * 9.0;
  CHECK(r.R_F_N == Approx(q * r.S_m2 * res::Ittc1957FrictionCoefficient(3.0 * 10.0 / res::kSeaWater15CViscosity)).epsilon(kRoundOff));
  CHECK(r.C_T == Approx(r.R_T_N / (q * r.S_m2)).epsilon(kRoundOff));
  CHECK_THROWS_AS(model.At(0.0, 1025.0, 9.81), std::invalid_argument);
  res::ResistanceOptions bad;
  bad.form_factor = 0.9;
  CHECK_THROWS_AS(res::CalmWaterResistance(WallSided(10.0, 0.5, 0.4, 0.1, 21), bad), std::invalid_argument);
}
