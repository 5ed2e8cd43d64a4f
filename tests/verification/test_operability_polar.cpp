// The operability polar (evaluation/operability_polar.h) on the Wigley hull of data/peers-oblique/ at 20 times
// its size (L 60 m; ship-scale seas, so that MSI is well above 0), 16 stations x 10 panels, 30 frequencies:
//  - at β = 180° the share of a scatter diagram meeting an rms vertical acceleration and an MSI limit equals
//    the head-sea operability (seas/operability.h: sk::EvaluateOperability on a RaoTable of the same heave
//    and pitch RAOs), with the limits placed between cell values so that no cell sits on a limit;
//  - a (speed, heading) whose encounter frequency reaches 0 on the grid (following seas at speed) is not
//    solved and is marked; at zero speed every heading is computed;
//  - a roll limit far below any roll holds in head seas (no roll on a symmetric hull) and fails in beam seas;
//  - limits no sea reaches give operability 1;
//  - bad options are refused with the field named;
//  - a built monohull design (the MONa form of Table 1, coarse strips) with the viscous roll damping: in beam
//    seas a roll limit between the rms roll of the design solved without and with Ikeda's damping (each from
//    eval::SolveObliqueDesign and the point statistics) fails in the polar without it and holds with it, and
//    the hull, outside the fitted range (Cb 0.39 < 0.5), is flagged at the polar's speed, as is the design's
//    method (the time-domain strip method) below its Froude range.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "evaluation/design_spec.h"
#include "evaluation/oblique_design.h"
#include "evaluation/oblique_point_response.h"
#include "evaluation/operability_polar.h"
#include "seakeeping/motions/oblique_strip_theory.h"
#include "seas/operability.h"
#include "support/wigley_oblique.h"

using namespace hullopt;

namespace {
constexpr double kG = 9.81;  // as test::WigleyObliqueOptions
constexpr double kScale = 20.0, kL = kScale * test::kWigleyL;
const double kU = 0.3 * std::sqrt(kG * kL);  // Fn 0.3, 7.3 m/s

std::vector<double> Grid() {
  std::vector<double> w;
  for (int i = 0; i < 30; ++i) w.push_back(0.2 + 2.8 * i / 29);
  return w;
}

eval::ObliqueSolve Solver(std::vector<std::vector<double>>* asked = nullptr) {
  return [asked](double U, const std::vector<double>& headings) {
    if (asked) asked->push_back(headings);
    static const auto stations = test::WigleyShipStations(kScale, 16, 10);
    return sk::SolveObliqueStripTheory(stations, test::WigleyShipMass(kScale, 3.0), Grid(), headings,
                                       test::WigleyObliqueOptions(U));
  };
}

// Seas Hs 1–5 m, Tz 5–9 s, probabilities 1/15 each.
sk::ScatterDiagram Diagram() {
  sk::ScatterDiagram d;
  for (double hs : {1.0, 2.0, 3.0, 4.0, 5.0})
    for (double tz : {5.0, 7.0, 9.0}) d.cells.push_back({hs, tz, 1.0 / 15.0});
  return d;
}

const sk::HullExtent kHull{0.5 * kL, 0.5 * kL};

eval::PolarOptions Options(std::vector<double> speeds, std::vector<double> headings) {
  eval::PolarOptions o;
  o.speeds_m_s = speeds;
  o.headings_deg = headings;
  o.omega_rad_s = Grid();
  return o;
}

// A limit half-way (geometrically) between the sorted values i − 1 and i, i = fraction × their number.
double LimitBetween(std::vector<double> v, double fraction) {
  std::sort(v.begin(), v.end());
  const std::size_t i = static_cast<std::size_t>(fraction * v.size());
  return std::sqrt(v[i - 1] * v[i]);
}
}  // namespace

TEST_CASE("operability polar at 180 deg equals the head-sea operability", "[verification][oblique]") {
  const sk::ObliqueStripResult r = Solver()(kU, {180.0});
  sk::RaoTable table;
  table.speed_m_s = kU;
  table.g_m_s2 = kG;
  for (std::size_t f = 0; f < Grid().size(); ++f) {
    const sk::ObliqueWaveResult& w = r.Wave(0, f);
    table.omega_rad_s.push_back(w.omega_rad_s);
    table.omega_e_rad_s.push_back(w.omega_rad_s + w.omega_rad_s * w.omega_rad_s * kU / kG);
    table.heave.push_back(w.rao[2]);
    table.pitch.push_back(w.rao[4]);
  }
  const sk::ScatterDiagram d = Diagram();
  // The head-sea values of every cell place the limits.
  sk::OperabilityCriterion probe{"probe", "lcg", false, 1.0};
  const sk::OperabilityResult head0 = sk::EvaluateOperability(table, kHull, d, {probe});
  std::vector<double> accel, msi;
  for (const auto& c : head0.cells) {
    accel.push_back(c.evaluation.positions[1].rms_accel_g);
    msi.push_back(c.evaluation.mean.msi_pct);
  }
  const double a_lim = LimitBetween(accel, 0.5), msi_lim = LimitBetween(msi, 0.7);
  const sk::OperabilityResult head = sk::EvaluateOperability(
      table, kHull, d, {{"a", "lcg", false, a_lim}, {"m", "mean", true, msi_lim}});
  std::vector<eval::PolarCriterion> criteria(2);
  criteria[0] = {"a", eval::PolarQuantity::kRmsVerticalAcceleration, "lcg", 0.0, 0.0, a_lim, ""};
  criteria[1] = {"m", eval::PolarQuantity::kMsi, "mean", 0.0, 0.0, msi_lim, ""};
  const eval::OperabilityPolar p =
      eval::ComputeOperabilityPolar(Solver(), kG, kHull, d, criteria, {}, Options({kU}, {180.0}));
  REQUIRE(p.cells.size() == 1);
  std::printf("180 deg: limits %.4f g, %.4f %%: polar %.4f %.4f all %.4f; head seas %.4f %.4f all %.4f\n", a_lim,
              msi_lim, p.cells[0].criterion_share[0], p.cells[0].criterion_share[1], p.cells[0].operability,
              head.criterion_time_pct[0] / 100, head.criterion_time_pct[1] / 100, head.all_criteria_time_pct / 100);
  // Shares are sums of whole cells (1/15 each) and no cell is within the interpolation difference of the
  // two paths (test_oblique_point_response: < 0.2 %) of a limit, so they are equal to rounding.
  constexpr double kShareTol = 1e-12;
  CHECK(p.cells[0].criterion_share[0] == Approx(head.criterion_time_pct[0] / 100).margin(kShareTol));
  CHECK(p.cells[0].criterion_share[1] == Approx(head.criterion_time_pct[1] / 100).margin(kShareTol));
  CHECK(p.cells[0].operability == Approx(head.all_criteria_time_pct / 100).margin(kShareTol));
  CHECK(p.cells[0].operability > 0.0);  // the check is not empty: some cells hold, some fail
  CHECK(p.cells[0].operability < 1.0);
}

TEST_CASE("operability polar marks encounter frequencies <= 0 and judges roll", "[verification][oblique]") {
  std::vector<std::vector<double>> asked;
  std::vector<eval::PolarCriterion> criteria(1);
  criteria[0] = {"roll", eval::PolarQuantity::kRmsRoll, "", 0.0, 0.0, 1e-6, ""};  // 1e-6 deg: no real roll
  const eval::OperabilityPolar p = eval::ComputeOperabilityPolar(Solver(&asked), kG, kHull, Diagram(), criteria,
                                                                 {}, Options({0.0, kU}, {0.0, 90.0, 180.0}));
  REQUIRE(p.cells.size() == 6);
  // Zero speed: every heading solved. At speed: following seas (ω_e = 0 at g/U = 1.35 rad/s < 3) left out.
  REQUIRE(asked.size() == 2);
  CHECK(asked[0] == std::vector<double>{0.0, 90.0, 180.0});
  CHECK(asked[1] == std::vector<double>{90.0, 180.0});
  CHECK(!p.cells[3].computed);
  CHECK(std::isnan(p.cells[3].operability));
  CHECK(p.cells[3].note.find("encounter frequency <= 0") != std::string::npos);
  CHECK(eval::ZeroEncounterWaveFrequency(kU, 0.0, kG) == Approx(kG / kU).epsilon(1e-12));
  for (std::size_t s : {0u, 1u}) {
    const std::size_t base = 3 * s;
    CHECK(p.cells[base + 2].operability == 1.0);  // head seas: no roll on the symmetric hull
    CHECK(p.cells[base + 1].operability == 0.0);  // beam seas: it rolls in every sea
  }
  CHECK(p.cells[0].operability == 1.0);  // following seas at zero speed: no roll either
  // Limits no sea reaches: every computed cell is operable all the time.
  std::vector<eval::PolarCriterion> lax(4);
  lax[0] = {"a", eval::PolarQuantity::kRmsVerticalAcceleration, "forward", 0.0, 2.0, 10.0, ""};
  lax[1] = {"y", eval::PolarQuantity::kRmsLateralAcceleration, "mean", 1.0, 2.0, 10.0, ""};
  lax[2] = {"r", eval::PolarQuantity::kRmsRoll, "", 0.0, 0.0, 40.0, ""};
  lax[3] = {"m", eval::PolarQuantity::kMsi, "transom", 0.0, 0.0, 100.0, ""};
  const eval::OperabilityPolar q =
      eval::ComputeOperabilityPolar(Solver(), kG, kHull, Diagram(), lax, {}, Options({kU}, {90.0, 135.0}));
  for (const auto& c : q.cells) CHECK(c.operability == Approx(1.0).margin(1e-12));  // sum of the 15 cells
}

TEST_CASE("operability polar refuses bad options", "[verification][oblique]") {
  std::vector<eval::PolarCriterion> criteria(1);
  criteria[0] = {"roll", eval::PolarQuantity::kRmsRoll, "", 0.0, 0.0, 4.0, ""};
  auto refuses = [&](const eval::PolarOptions& o, const char* what) {
    try {
      eval::ComputeOperabilityPolar(Solver(), kG, kHull, Diagram(), criteria, {}, o);
      FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find(what) != std::string::npos);
    }
  };
  refuses(Options({kU}, {360.0}), "headings_deg[0] = 360");
  refuses(Options({kU}, {-10.0}), "within [0, 360)");
  refuses(Options({-1.0}, {180.0}), "speeds[0] = -1");
  refuses(Options({kU}, {90.0, 90.0}), "given twice");
  std::vector<eval::PolarCriterion> bad(1);
  bad[0] = {"x", eval::PolarQuantity::kMsi, "bridge", 0.0, 0.0, 10.0, ""};
  CHECK_THROWS_AS(eval::ComputeOperabilityPolar(Solver(), kG, kHull, Diagram(), bad, {}, Options({kU}, {180.0})),
                  std::invalid_argument);
}

namespace {
// MONa (Davis & Holloway 2003, Table 1, hull 14; configs/polar-mona-40kn.yaml) on 12 sections x 6 panels.
eval::DesignCase MonaDesign() {
  eval::DesignSpec spec;
  spec.source = "typed";
  auto& v = spec.hull.variables;
  v.type = hull::HullType::kMonohull;
  v.section_style = hull::SectionStyle::kRoundBilge;
  v.displacement_t = 1000;
  v.L_over_B = 11.9;
  v.B_over_T = 4.51;
  v.Cb = 0.39;
  v.Cp = 0.60;
  v.Cwp = 0.66;
  v.LCB_pct_L = -9.6;
  v.LCF_pct_L = -15.5;
  v.transom_immersion = 0.3;
  v.transom_beam_ratio = 1.0;
  v.keel_rise = 0.3;
  spec.speed.unit = eval::SpeedOptions::Unit::kKnots;
  spec.speed.value = 20;
  spec.solver.rao.sections = 12;
  spec.solver.rao.panels = 6;
  spec.solver.grid.enabled = false;
  spec.mass.kg_m = 4.0;
  return eval::BuildDesign(spec);
}
}  // namespace

TEST_CASE("operability polar of a design with the viscous roll damping", "[verification][oblique]") {
  const eval::DesignCase d = MonaDesign();
  const double U = d.speed_m_s, kxx = eval::DefaultRollRadiusOfGyration(d.hull);
  std::vector<double> grid;
  for (int i = 0; i < 24; ++i) grid.push_back(0.3 + 2.0 * i / 23);
  sk::RollDampingOptions ikeda;
  ikeda.model = sk::RollDampingModel::kIkeda;
  // The rms roll in one beam sea, potential damping only and with Ikeda's components.
  const sk::SeaState sea = sk::SeaState::BretschneiderTz(2.0, 7.5);
  const sk::WaveSpectrum spectrum(sea);
  const sk::ObliqueStripResult r0 = eval::SolveObliqueDesign(d, U, grid, {90.0}, kxx);
  sk::ObliqueStripOptions with;
  eval::SetDesignRollDamping(d, ikeda, &with);
  const sk::ObliqueStripResult r1 = eval::SolveObliqueDesign(d, U, grid, {90.0}, kxx, with);
  const double roll0 = eval::ObliqueStatisticsInSea(r0, 0, d.water.g_m_s2, spectrum, {}).rms_roll_rad * 180 / M_PI;
  const double roll1 = eval::ObliqueStatisticsInSea(r1, 0, d.water.g_m_s2, spectrum, {}).rms_roll_rad * 180 / M_PI;
  std::printf("MONa 20 kn, 90 deg, Hs 2 m Tz 7.5 s: rms roll %.3f deg potential, %.3f deg with Ikeda\n", roll0,
              roll1);
  REQUIRE(roll1 < roll0);  // viscous damping only adds to B44
  sk::ScatterDiagram diagram;
  diagram.cells.push_back({sea.Hs_m, sea.Tz_s, 1.0});
  diagram.spectrum = sk::SpectrumType::kBretschneider;
  diagram.gamma = 1.0;
  std::vector<eval::PolarCriterion> criteria(1);
  criteria[0] = {"roll", eval::PolarQuantity::kRmsRoll, "", 0.0, 0.0, std::sqrt(roll0 * roll1), ""};
  eval::PolarOptions o;
  o.speeds_m_s = {U};
  o.headings_deg = {90.0};
  o.omega_rad_s = grid;
  const eval::OperabilityPolar none = eval::ComputeOperabilityPolar(d, kxx, diagram, criteria, {}, o);
  o.roll_damping = ikeda;
  const eval::OperabilityPolar viscous = eval::ComputeOperabilityPolar(d, kxx, diagram, criteria, {}, o);
  CHECK(none.cells[0].operability == 0.0);
  CHECK(viscous.cells[0].operability == 1.0);
  CHECK(none.roll_damping == "potential only");
  // The design's method, the time-domain strip method, is below its Froude range at 20 kn (Fn 0.30): that is
  // flagged at this speed, and with potential roll damping it is the only flag.
  CHECK(none.method.find("time-domain strip method") != std::string::npos);
  REQUIRE(none.flags.size() == 1);
  CHECK(none.flags[0].text.find("below the validity range") != std::string::npos);
  CHECK(none.flags[0].speeds_m_s == std::vector<double>{U});
  CHECK(viscous.roll_damping.find("Ikeda's components") != std::string::npos);
  bool cb = false;
  for (const auto& f : viscous.flags) {
    std::printf("flag: %s\n", f.text.c_str());
    CHECK(f.speeds_m_s == std::vector<double>{U});
    cb = cb || f.text.find("Cb") != std::string::npos;
  }
  CHECK(cb);
}
