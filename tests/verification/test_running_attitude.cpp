// Running attitude (parametric_hull/running_attitude.h): a trimmed and sunk box and a trimmed V-section
// ("wedge") hull against closed-form displaced volume, LCB and waterplane; the strip sections see the local
// draught T + s − (x − x_p) tan θ; even keel is the hull itself, bitwise; the refusal rules.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "parametric_hull/hull_generator.h"
#include "parametric_hull/hydrostatics.h"
#include "parametric_hull/running_attitude.h"
#include "seakeeping/strip/strip_geometry.h"

namespace hull = hullopt::hull;
namespace sk = hullopt::sk;

namespace {
// Hydrostatics integrate polylines exactly and use Simpson along x, exact for the linear (box) and quadratic
// (wedge) sectional area curves here: agreement to round-off, with room for the sums of ~100 terms.
constexpr double kRoundOff = 1e-12;

// A prismatic monohull of length L with the half-section `y` (keel) .. `deck` at every station, stations every
// L/20 (Simpson needs an even count of intervals).
hull::HullForm Prism(double L, double T, std::vector<double> y, std::vector<double> z) {
  hull::HullForm h;
  h.type = "monohull";
  h.draught_m = T;
  h.length_m = L;
  hull::Demihull b;
  b.role = "main";
  for (int i = 0; i <= 20; ++i) b.stations.push_back({L * i / 20.0, y, z});
  h.bodies = {b};
  return h;
}
// Box L × B with its deck at `deck`.
hull::HullForm Box(double L, double B, double T, double deck) {
  return Prism(L, T, {0.0, B / 2, B / 2}, {0.0, 0.0, deck});
}
// Wedge: V sections with half-breadth y = k z, keel on the baseline, to z = deck.
hull::HullForm Wedge(double L, double k, double T, double deck) { return Prism(L, T, {0.0, k * deck}, {0.0, deck}); }
}  // namespace

TEST_CASE("trimmed, sunk box: volume, LCB and LCF in closed form", "[attitude]") {
  const double L = 20, B = 4, T = 1.0, xp = 8.0, s = 0.05, trim = 1.5;  // bow up
  const double t = std::tan(trim * M_PI / 180);
  const auto h = hull::ApplyRunningAttitude(Box(L, B, T, 2.5), {s, trim, xp});
  const auto hs = hull::ComputeHydrostatics(h, 1025.0);
  // d(x) = T + s − (x − xp) t; ∇ = B ∫ d, ∇·LCB = B ∫ x d over [0, L].
  const double c = T + s + xp * t;
  const double V = B * (c * L - t * L * L / 2), Vx = B * (c * L * L / 2 - t * L * L * L / 3);
  CHECK(hs.volume_m3 == Approx(V).epsilon(kRoundOff));
  CHECK(hs.lcb_m_from_ap == Approx(Vx / V).epsilon(kRoundOff));
  CHECK(hs.lcb_m_from_ap < L / 2);  // bow up: buoyancy moves aft
  CHECK(hs.awp_m2 == Approx(B * L).epsilon(kRoundOff));  // wall-sided: the waterplane does not change
  CHECK(hs.lcf_m_from_ap == Approx(L / 2).epsilon(kRoundOff));
}

TEST_CASE("trimmed wedge: volume, LCB and waterplane in closed form", "[attitude]") {
  const double L = 30, k = 0.8, T = 1.2, xp = 14.0, s = -0.03, trim = -2.0;  // rises 3 cm, bow down 2°
  const double t = std::tan(trim * M_PI / 180);
  const auto h = hull::ApplyRunningAttitude(Wedge(L, k, T, 3.0), {s, trim, xp});
  const auto hs = hull::ComputeHydrostatics(h, 1025.0);
  // d(x) = c − t x; section area 2·(k d²/2) = k d²; waterline breadth 2 k d.
  const double c = T + s + xp * t;
  auto I = [&](int n) {  // ∫_0^L x^n d(x)^2 dx
    double sum = 0;
    const double a[3] = {c * c, -2 * c * t, t * t};
    for (int j = 0; j < 3; ++j) sum += a[j] * std::pow(L, n + j + 1) / (n + j + 1);
    return sum;
  };
  CHECK(hs.volume_m3 == Approx(k * I(0)).epsilon(kRoundOff));
  CHECK(hs.lcb_m_from_ap == Approx(I(1) / I(0)).epsilon(kRoundOff));
  const double Awp = 2 * k * (c * L - t * L * L / 2);
  CHECK(hs.awp_m2 == Approx(Awp).epsilon(kRoundOff));
  CHECK(hs.lcb_m_from_ap > L / 2);  // bow down: buoyancy moves forward
}

TEST_CASE("strip sections see the local draught of the trimmed hull", "[attitude]") {
  const double L = 20, B = 4, T = 1.0, xp = 8.0, s = 0.05, trim = 1.5;
  const double t = std::tan(trim * M_PI / 180);
  const auto h = hull::ApplyRunningAttitude(Box(L, B, T, 2.5), {s, trim, xp});
  sk::StripGeometryOptions o;
  o.sections = 16;
  o.panels = 10;
  const auto kernel = sk::StripKernelGeometry(h, o, 5.0, 1025.0, 9.81);
  for (int n = 0; n < kernel.Steps(); ++n) {
    double zmin = 0;
    for (const auto& p : kernel.panels[n]) zmin = std::min({zmin, p.z1, p.z2});
    CHECK(-zmin == Approx(T + s - (kernel.x_m[n] - xp) * t).epsilon(kRoundOff));
  }
}

TEST_CASE("even keel is the hull itself, bitwise", "[attitude]") {
  hull::DesignVariables dv;  // the default catamaran
  const auto h = hull::GenerateHull(dv);
  const auto a = hull::ApplyRunningAttitude(h, {0.0, 0.0, 37.0});
  REQUIRE(a.bodies.size() == h.bodies.size());
  for (std::size_t b = 0; b < h.bodies.size(); ++b)
    for (std::size_t i = 0; i < h.bodies[b].stations.size(); ++i) {
      CHECK(a.bodies[b].stations[i].z_m == h.bodies[b].stations[i].z_m);
      CHECK(a.bodies[b].stations[i].y_m == h.bodies[b].stations[i].y_m);
    }
}

TEST_CASE("attitude refusals: deck submerged, transom or run lifted out, trim beyond the small-angle bound",
          "[attitude]") {
  const double L = 20, B = 4, T = 1.0;
  const auto box = Box(L, B, T, 1.3);
  // Bow up 3° about midships: the stern sinks by 10 tan 3° = 0.52 m, deck freeboard is 0.3 m.
  CHECK_THROWS_WITH(hull::ApplyRunningAttitude(box, {0.0, 3.0, 10.0}),
                    Catch::Contains("deck edge") && Catch::Contains("x = 0 m"));
  // A sinkage deeper than the freeboard.
  CHECK_THROWS_WITH(hull::ApplyRunningAttitude(box, {0.35, 0.0, 10.0}), Catch::Contains("deck edge"));
  // A rise that lifts the whole box out.
  CHECK_THROWS_AS(hull::ApplyRunningAttitude(box, {-1.2, 0.0, 10.0}), std::domain_error);
  // Wedge with a rising forefoot: bow up lifts the forward stations; the stern lifting is refused.
  auto fore = Wedge(L, 0.8, T, 3.0);
  for (auto& st : fore.bodies[0].stations)  // keel rises linearly over the forward 20%: 0.95 T at the stem
    if (st.x_m > 0.8 * L)
      for (auto& z : st.z_m) z += 0.95 * T * (st.x_m - 0.8 * L) / (0.2 * L) * (z == 0.0 ? 1.0 : 0.0);
  // Bow up 1° about midships, rise 0.1 m: the stem region (keel within 0.27 m of the water) emerges: allowed.
  CHECK_NOTHROW(hull::ApplyRunningAttitude(fore, {-0.1, 1.0, 10.0}));
  // Bow down 2.5° about the stem: the stern rises 20 tan 2.5° = 0.87 m, rise 0.2 m: the transom emerges.
  CHECK_THROWS_WITH(hull::ApplyRunningAttitude(fore, {-0.2, -2.5, 20.0}),
                    Catch::Contains("lifted out") && Catch::Contains("x = 0 m"));
  CHECK_THROWS_AS(hull::ApplyRunningAttitude(box, {0.0, 6.0, 10.0}), std::invalid_argument);
}
