// Plausibility rules against closed forms: a box-shaped hull has Cb = Cp = Cm = Cwp = 1 exactly, a pair of box
// demihulls of beam B at centre spacing s has the clearance s - B, and a box of L x B x T displaces rho L B T.
#include <catch2/catch.hpp>

#include <string>

#include "parametric_hull/hydrostatics.h"
#include "parametric_hull/plausibility.h"

using namespace hullopt::hull;

namespace {
// Box demihull: length L, half-breadth b, depth D (>= T), `n` stations.
Demihull Box(double L, double b, double D, int n = 11) {
  Demihull d;
  d.role = "main";
  for (int i = 0; i < n; ++i) {
    Station s;
    s.x_m = L * i / (n - 1);
    for (double y : {0.0, b, b}) s.y_m.push_back(y);  // push_back: gcc 12 warns falsely on = {...}
    for (double z : {0.0, 0.0, D}) s.z_m.push_back(z);
    d.stations.push_back(s);
  }
  return d;
}
HullForm BoxHull(double L, double B, double T, double spacing = 0.0) {
  HullForm h;
  h.type = spacing > 0 ? "catamaran" : "monohull";
  h.draught_m = T;
  Demihull d = Box(L, B / 2, 2 * T);
  if (spacing > 0) d.role = "demihull", d.y_centre_m = spacing / 2;
  h.bodies = {d};
  return h;
}
bool Refuses(const std::vector<PlausibilityFinding>& f, const std::string& quantity) {
  for (const auto& x : f)
    if (x.refuse && x.quantity == quantity) return true;
  return false;
}
}  // namespace

TEST_CASE("a box hull passes: coefficients 1 are inside (0, 1]", "[plausibility]") {
  const HullForm h = BoxHull(20.0, 2.0, 1.0);
  const Hydrostatics hs = ComputeHydrostatics(h);
  CHECK(hs.Cb == Approx(1.0).epsilon(1e-12));
  CHECK(CheckHullPlausibility(h, hs).empty());
}

TEST_CASE("box demihulls: clearance is spacing minus beam; overlap is refused", "[plausibility]") {
  const double L = 20.0, B = 2.0, T = 1.0;
  for (double s : {1.0, 2.5, 6.0}) {
    const HullForm h = BoxHull(L, B, T, s);
    const Hydrostatics hs = ComputeHydrostatics(h);
    CHECK(DemihullClearance(h, hs) == Approx(s - B).margin(1e-12));
    CHECK(Refuses(CheckHullPlausibility(h, hs), "spacing") == (s <= B));
  }
}

TEST_CASE("offsets in millimetres with the draught in metres name the unit error", "[plausibility]") {
  HullForm h = BoxHull(3000.0, 300.0, 0.15);  // a 3 m x 0.3 m model in mm, T = 0.15 m
  const Hydrostatics hs = ComputeHydrostatics(h);
  const auto f = CheckHullPlausibility(h, hs);
  REQUIRE(Refuses(f, "L"));
  CHECK(f.front().message.find("millimetres") != std::string::npos);
}

TEST_CASE("a length override far from the stations' span is refused", "[plausibility]") {
  HullForm h = BoxHull(3.0, 0.3, 0.15);
  h.length_m = 0.5;  // Cb would be 6
  CHECK(Refuses(CheckHullPlausibility(h, ComputeHydrostatics(h)), "length_m"));
  h.length_m = 3.1;  // a stem beyond the last station: fine
  CHECK(CheckHullPlausibility(h, ComputeHydrostatics(h)).empty());
}

TEST_CASE("mass against rho L B T, k_yy and KG ranges", "[plausibility]") {
  const double L = 20.0, B = 2.0, T = 1.0, rho = 1025.0;
  const HullForm h = BoxHull(L, B, T);
  const Hydrostatics hs = ComputeHydrostatics(h, rho, T);
  const double displaced = rho * L * B * T;  // closed form of the box
  MassProperties m;
  m.kyy_m = 0.25 * L;
  m.kg_m = T;
  m.mass_kg = 1.015 * displaced;  // inside the 2 % tolerance
  CHECK(CheckMassPlausibility(m, hs, false).empty());
  m.mass_kg = 1.03 * displaced;
  CHECK(Refuses(CheckMassPlausibility(m, hs, false), "mass_kg"));
  const auto accepted = CheckMassPlausibility(m, hs, true);
  REQUIRE(accepted.size() == 1);
  CHECK_FALSE(accepted.front().refuse);  // a warning when accepted
  m.mass_kg = displaced;
  m.kyy_m = 0.6 * L;  // beyond all mass at the ends (0.5 L)
  CHECK(Refuses(CheckMassPlausibility(m, hs, false), "kyy_m"));
  m.kyy_m = 0.4 * L;  // possible but unusual: a warning
  const auto unusual = CheckMassPlausibility(m, hs, false);
  REQUIRE(unusual.size() == 1);
  CHECK_FALSE(unusual.front().refuse);
  m.kyy_m = 0.25 * L;
  m.kg_m = 0.0;
  CHECK(Refuses(CheckMassPlausibility(m, hs, false), "kg_m"));
}
