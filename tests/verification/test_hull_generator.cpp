// The parametric generator meets its targets in its own hydrostatics, for every hull type
// and section style; and refuses combinations that cannot be met, naming variables and rule.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "parametric_hull/form_curve.h"
#include "parametric_hull/hull_generator.h"
#include "parametric_hull/hydrostatics.h"

using namespace hullopt::hull;

namespace {
// Generator targets: coefficients within 0.005, LCB/LCF within 0.2 % L, displacement to 1e-6 relative.
constexpr double kCoefficientTol = 0.005, kCentroidTolPctL = 0.2, kDisplacementRelTol = 1e-6;

void CheckTargets(const DesignVariables& dv) {
  const HullForm h = GenerateHull(dv);
  const Hydrostatics hs = ComputeHydrostatics(h, dv.rho_kg_m3);
  CHECK(hs.displacement_t == Approx(dv.displacement_t).epsilon(kDisplacementRelTol));
  CHECK(hs.Cb == Approx(dv.Cb).margin(kCoefficientTol));
  CHECK(hs.Cp == Approx(dv.Cp).margin(kCoefficientTol));
  CHECK(hs.Cwp == Approx(dv.Cwp).margin(kCoefficientTol));
  CHECK(hs.LCB_pct_L == Approx(dv.LCB_pct_L).margin(kCentroidTolPctL));
  CHECK(hs.LCF_pct_L == Approx(dv.LCF_pct_L).margin(kCentroidTolPctL));
  CHECK(hs.L_m / hs.B_m == Approx(dv.L_over_B).epsilon(kCoefficientTol));
  CHECK(hs.B_m / hs.T_m == Approx(dv.B_over_T).epsilon(kCoefficientTol));
  for (const auto& b : h.bodies)
    for (const auto& s : b.stations)
      for (size_t k = 1; k < s.z_m.size(); ++k) REQUIRE(s.z_m[k] >= s.z_m[k - 1]);
}

DesignVariables Base(HullType type) {
  DesignVariables dv;
  dv.type = type;
  dv.section_style = type == HullType::kSwath ? SectionStyle::kSwathBulb : SectionStyle::kRoundBilge;
  return dv;
}

// SW1 of Table 1 (hull 9), with the previous (elliptic, scaled) bulb family unless a bulb height is given.
DesignVariables Sw1() {
  DesignVariables dv = Base(HullType::kSwath);
  dv.L_over_B = 16.1;
  dv.B_over_T = 1.51;
  dv.Cb = 0.55;
  dv.Cp = 0.75;
  dv.Cwp = 0.38;
  dv.LCB_pct_L = -10.9;
  dv.LCF_pct_L = -14.6;
  dv.strut_ratio = 0.7;
  dv.transom_beam_ratio = 0.3;
  dv.transom_immersion = 0.6;
  return dv;
}

std::string Refusal(const DesignVariables& dv) {
  try {
    GenerateHull(dv);
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("form curve closed-form area and moment agree with quadrature", "[generator][form_curve]") {
  // Independent check of the closed forms: composite midpoint rule with 200000 panels (error ~1e-9 even at
  // the kink of the peak).
  constexpr double kQuadratureTol = 1e-6;
  const auto curve = [](double xi_peak, double peak, double aft_ratio, double exponent, double run_ratio) {
    FormCurve c;
    c.xi_peak = xi_peak;
    c.peak = peak;
    c.aft_ratio = aft_ratio;
    c.exponent = exponent;
    c.run_ratio = run_ratio;
    return c;
  };
  const FormCurve c1 = curve(0.4, 1.2, 0.3, 2.5, 0.7), c2 = curve(0.7, 1.0, 0.0, 0.6, 3.0);
  FormCurve blend;  // a blend of the two, weights 0.3 / 0.7
  blend.members = {c1, c2};
  blend.weights = {0.3, 0.7};
  for (const FormCurve& c : {c1, c2, blend}) {
    const int n = 200000;
    double a = 0, m = 0;
    for (int i = 0; i < n; ++i) {
      const double xi = (i + 0.5) / n;
      a += c(xi) / n;
      m += xi * c(xi) / n;
    }
    CHECK(c.Area() == Approx(a).epsilon(kQuadratureTol));
    CHECK(c.Moment() == Approx(m).epsilon(kQuadratureTol));
  }
}

TEST_CASE("generated hulls meet their targets: all types and styles", "[generator]") {
  SECTION("catamaran, round bilge") { CheckTargets(Base(HullType::kCatamaran)); }
  SECTION("monohull, round bilge") {
    DesignVariables dv = Base(HullType::kMonohull);
    dv.L_over_B = 8.0;
    dv.B_over_T = 4.0;
    dv.Cp = 0.59;
    dv.Cwp = 0.84;
    dv.LCB_pct_L = -5.4;
    dv.LCF_pct_L = -6.3;
    CheckTargets(dv);
  }
  SECTION("catamaran, hard chine") {
    DesignVariables dv = Base(HullType::kCatamaran);
    dv.section_style = SectionStyle::kHardChine;
    dv.Cb = 0.59;
    dv.Cp = 0.74;
    dv.Cwp = 0.84;
    dv.LCB_pct_L = -11.0;
    dv.LCF_pct_L = -6.8;
    dv.transom_immersion = 0.6;
    dv.transom_beam_ratio = 0.7;
    CheckTargets(dv);
  }
  SECTION("SWATH") { CheckTargets(Sw1()); }
  SECTION("trihull") {
    DesignVariables dv = Base(HullType::kTrihull);
    dv.L_over_B = 8.0;
    dv.B_over_T = 5.35;
    dv.Cb = 0.38;
    dv.Cp = 0.80;
    dv.Cwp = 0.72;
    dv.LCB_pct_L = -11.8;
    dv.LCF_pct_L = -11.5;
    dv.transom_immersion = 0.4;
    dv.transom_beam_ratio = 0.3;
    dv.outrigger_L_over_B = 35;
    CheckTargets(dv);
    const HullForm h = GenerateHull(dv);
    REQUIRE(h.bodies.size() == 2);
    // Outriggers end at the transom and reach forward over 60 % of L.
    CHECK(h.bodies[1].stations.front().x_m == Approx(0.0).margin(1e-9));
    CHECK(h.bodies[1].stations.back().x_m == Approx(0.6 * h.length_m));
  }
}

TEST_CASE("impossible combinations are refused naming variables and rule", "[generator][bad-input]") {
  DesignVariables cm = Base(HullType::kCatamaran);
  cm.Cb = 0.72;
  cm.Cp = 0.69;  // Cm = Cb/Cp > 1
  CHECK_THAT(Refusal(cm), Catch::Contains("Cm = Cb/Cp") && Catch::Contains("must be <= 1"));

  DesignVariables cp = Base(HullType::kCatamaran);
  cp.Cp = 1.0;
  CHECK_THAT(Refusal(cp), Catch::Contains("Cp = 1") && Catch::Contains("must lie in (0, 1)"));

  DesignVariables swath = Base(HullType::kSwath);  // Cm = 0.58: a strut of 0.95 B alone has more area
  swath.strut_ratio = 0.95;
  CHECK_THAT(Refusal(swath), Catch::Contains("impossible SWATH") && Catch::Contains("Cm = Cb/Cp"));

  DesignVariables chine = Base(HullType::kCatamaran);  // Cm = 0.58 ok; but a fine hull with Cm 0.45 is not
  chine.section_style = SectionStyle::kHardChine;
  chine.Cb = 0.30;
  chine.Cp = 0.69;
  CHECK_THAT(Refusal(chine), Catch::Contains("hard-chine section") && Catch::Contains("0.5..1"));

  DesignVariables lcf = Base(HullType::kCatamaran);  // Cwp 0.9 with LCF -8: beyond the bound -5 % L
  lcf.Cwp = 0.9;
  lcf.LCF_pct_L = -8.0;
  CHECK_THAT(Refusal(lcf),
             Catch::Contains("Cwp = 0.9") && Catch::Contains("LCF_pct_L = -8") && Catch::Contains("rule"));

  DesignVariables style = Base(HullType::kCatamaran);
  style.section_style = SectionStyle::kSwathBulb;
  CHECK_THAT(Refusal(style), Catch::Contains("section_style"));
}

TEST_CASE("on_infeasible: nearest builds the nearest feasible waterplane and records the change",
          "[generator][infeasible]") {
  DesignVariables dv = Base(HullType::kCatamaran);  // Cwp 0.9 with LCF -8: beyond the bound -5 % L
  dv.Cwp = 0.9;
  dv.LCF_pct_L = -8.0;
  const std::string refusal = Refusal(dv);
  REQUIRE(refusal.find("nearest feasible: LCF_pct_L = ") != std::string::npos);
  dv.on_infeasible = OnInfeasible::kNearest;
  const HullForm h = GenerateHull(dv);
  REQUIRE(h.adjustments.size() == 1);
  const std::string& a = h.adjustments[0];
  const std::string to = a.substr(a.find("-> ") + 3);
  const double lcf = std::stod(to.substr(0, to.find(' ')));
  // Independent of the family: no waterplane no wider than its peak (1) of area 0.9 has its centroid aft of
  // (Cwp/2 - 1/2) 100 = -5 % L, so the nearest feasible LCF cannot lie aft of it.
  CHECK(lcf >= -5.0);
  CHECK(lcf < 0.0);
  // It is what was built (Cwp kept), and the refusal message named the same value.
  const Hydrostatics hs = ComputeHydrostatics(h, dv.rho_kg_m3);
  CHECK(hs.Cwp == Approx(0.9).margin(kCoefficientTol));
  CHECK(hs.LCF_pct_L == Approx(lcf).margin(kCentroidTolPctL));
  CHECK(refusal.find("LCF_pct_L = " + to.substr(0, to.find(' '))) != std::string::npos);
  // Nearest: 0.25 % L further aft is refused again.
  DesignVariables aft = dv;
  aft.on_infeasible = OnInfeasible::kRefuse;
  aft.LCF_pct_L = lcf - 0.25;
  CHECK_THAT(Refusal(aft), Catch::Contains("beyond the fair-curve family") && Catch::Contains("nearest feasible"));
  // A feasible design is built unchanged.
  CHECK(GenerateHull(Base(HullType::kCatamaran)).adjustments.empty());
}

TEST_CASE("rounded-bulb SWATH: targets met, the bulb keeps its height to the ends (no thin plates)",
          "[generator][swath]") {
  DesignVariables dv = Sw1();
  dv.bulb_height_ratio = 0.8;
  CheckTargets(dv);
  const HullForm h = GenerateHull(dv);
  const double T = h.draught_m;
  // Every station whose section stands out of its strut (a bulb) is at least as tall, over the part wider than
  // the strut, as a quarter of the draught: the old family flattened to a few per cent of T towards the bow.
  constexpr double kMinBulbHeightOverT = 0.25;
  int bulbs = 0;
  for (const auto& s : h.bodies[0].stations) {
    if (s.y_m.size() < 3) continue;
    const double strut = s.y_m.back();
    double z_lo = INFINITY, z_hi = -INFINITY;
    for (size_t k = 0; k < s.y_m.size(); ++k)
      if (s.y_m[k] > 1.05 * strut && s.z_m[k] < T) z_lo = std::min(z_lo, s.z_m[k]), z_hi = std::max(z_hi, s.z_m[k]);
    if (!std::isfinite(z_lo)) continue;
    ++bulbs;
    INFO("x = " << s.x_m);
    CHECK((z_hi - z_lo) / T > kMinBulbHeightOverT);
  }
  CHECK(bulbs > 20);
  // A bulb too low for Cm is refused naming the variable.
  dv.bulb_height_ratio = 0.3;
  CHECK_THAT(Refusal(dv), Catch::Contains("bulb_height_ratio"));
}
