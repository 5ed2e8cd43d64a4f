// The campaign objective averaged over headings (eval::MsiObjectiveOptions::headings_deg, heading_weights) on
// the default catamaran of configs/optimize-catamaran.yaml at 40 kn, coarse strips (10 sections x 6 panels,
// 20 wave frequencies, no adaptive grid) and two JONSWAP seas:
//  - one heading, 150 deg: the objective equals the mean MSI at the three passenger positions computed here by
//    the oblique point-response path (eval::SolveObliqueDesign of the trial design on its sea frequencies,
//    eval::ObliqueStatisticsInSea at forward, LCG and transom on the centreline), averaged over the seas;
//  - weights (1, 0) over headings (150, 120) give the 150 deg objective, (0, 1) the 120 deg one, and
//    (3, 1) their 0.75/0.25 mix (the weights are normalised);
//  - headings [180] is the head-sea objective without headings, bit for bit (the time-domain strip method);
//    [180, 150] with weights (1, 0) is 180 deg by the time-domain oblique path, whose heave and pitch are the
//    head-sea path's to round-off, so that it equals the head-sea objective through another point response
//    (its interpolation in the wave frequency rather than the encounter frequency aside);
//    with solver.method strip_theory_stf the oblique-sea strip theory with the design's Cs is taken instead;
//  - bad headings and weights are refused with the field named.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "evaluation/design_case.h"
#include "evaluation/msi_evaluator.h"
#include "evaluation/oblique_design.h"
#include "evaluation/oblique_point_response.h"
#include "evaluation/trial_design.h"
#include "seas/passenger_positions.h"

using namespace hullopt;

namespace {
const std::vector<std::string> kNames = {"L_over_B"};
const std::vector<double> kX = {11.0};

eval::DesignBasis Basis() {
  eval::DesignBasis b;
  b.config_file = "typed";
  auto& v = b.variables;
  v.type = hull::HullType::kCatamaran;
  v.section_style = hull::SectionStyle::kRoundBilge;
  v.displacement_t = 1000;
  v.L_over_B = 11.0;
  v.B_over_T = 2.0;
  v.Cb = 0.40;
  v.Cp = 0.69;
  v.Cwp = 0.76;
  v.LCB_pct_L = -6.4;
  v.LCF_pct_L = -8.3;
  v.transom_immersion = 0.3;
  v.spacing_over_L = 0.25;
  b.speed.unit = eval::SpeedOptions::Unit::kKnots;
  b.speed.value = 40;
  b.solver.rao.motion.damping_cs = 0.065;
  b.solver.rao.sections = 10;
  b.solver.rao.panels = 6;
  b.solver.grid.enabled = false;
  // 20 wave frequencies over the seas' energy (0.3-2.6 rad/s; the default 60 make the test minutes long).
  b.solver.frequencies = sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kOmega, 0.3, 2.6, 20);
  b.has_frequencies = true;
  return b;
}

eval::MsiObjectiveOptions Options(std::vector<double> headings, std::vector<double> weights = {}) {
  eval::MsiObjectiveOptions o;
  o.seas = {sk::SeaState::JonswapTz(1.0, 5.5), sk::SeaState::JonswapTz(3.0, 7.5)};
  o.sea_weights = {1.0, 1.0};
  o.headings_deg = std::move(headings);
  o.heading_weights = std::move(weights);
  return o;
}

double Objective(const eval::MsiObjectiveOptions& o) {
  auto e = eval::MakeMsiEvaluator(Basis(), kNames, o);
  const opt::EvalResult r = e->Evaluate(kX);
  INFO(r.error);
  REQUIRE(r.produced);
  return r.objective;
}

// The mean MSI [%] at forward, LCG and transom over the two seas, heading `heading_deg`, by the oblique
// point-response path on the trial design.
double ObliqueMeanMsi(double heading_deg, const eval::DesignBasis& basis = Basis()) {
  const eval::DesignCase d = eval::BuildTrialDesign(basis, eval::TrialFields(kNames), kX);
  const sk::ObliqueStripResult r = eval::SolveObliqueDesign(d, d.speed_m_s, eval::SeaFrequencies(d), {heading_deg},
                                                            eval::DefaultRollRadiusOfGyration(d.hull));
  std::vector<eval::ShipPoint> points;
  for (const auto& p : sk::StandardPassengerPositions(d.Extent().cg_to_transom_m))
    points.push_back({p.name, p.x_from_cg_m, 0.0, 0.0});
  double sum = 0.0;
  for (const sk::SeaState& sea : Options({}).seas) {
    const eval::ObliqueSeaStatistics st =
        eval::ObliqueStatisticsInSea(r, 0, d.water.g_m_s2, sk::WaveSpectrum(sea), points);
    REQUIRE(st.points.size() == 3);
    sum += (st.points[0].msi_pct + st.points[1].msi_pct + st.points[2].msi_pct) / 3.0;
  }
  return sum / 2.0;
}
}  // namespace

TEST_CASE("one-heading objective equals the oblique point-response MSI", "[verification][oblique]") {
  const double objective = Objective(Options({150.0}));
  const double direct = ObliqueMeanMsi(150.0);
  std::printf("150 deg: objective %.12g %%, oblique point response %.12g %%\n", objective, direct);
  // The same sums in another order (the seas' weighted mean there, the plain mean here): rounding only.
  constexpr double kRoundingTol = 1e-12;
  CHECK(objective == Approx(direct).epsilon(kRoundingTol));
  CHECK(objective > 1.0);  // the seas give a real MSI, so the comparison is not of zeros
}

TEST_CASE("heading weights select and mix the headings", "[verification][oblique]") {
  const double a = Objective(Options({150.0}));
  const double b = Objective(Options({120.0}));
  const double first = Objective(Options({150.0, 120.0}, {1.0, 0.0}));
  const double second = Objective(Options({150.0, 120.0}, {0.0, 1.0}));
  const double mix = Objective(Options({150.0, 120.0}, {3.0, 1.0}));  // 5 evaluations, each a few seconds
  std::printf("150 deg %.10g, 120 deg %.10g; weights (1,0) %.10g, (0,1) %.10g, (3,1) %.10g\n", a, b, first, second,
              mix);
  // Each heading's motions do not depend on the other headings solved with it; a zero weight adds 0 exactly.
  constexpr double kRoundingTol = 1e-12;
  CHECK(first == Approx(a).epsilon(kRoundingTol));
  CHECK(second == Approx(b).epsilon(kRoundingTol));
  CHECK(mix == Approx(0.75 * a + 0.25 * b).epsilon(kRoundingTol));
  CHECK(std::fabs(a - b) > 1e-3 * a);  // the headings differ, so the weights are seen
}

TEST_CASE("headings [180] is the head-sea objective, bit for bit", "[verification][oblique]") {
  const double none = Objective(Options({}));
  const double head = Objective(Options({180.0}));
  CHECK(head == none);  // bitwise: the same path
  const double oblique180 = Objective(Options({180.0, 150.0}, {1.0, 0.0}));
  std::printf("head seas: head-sea path %.12g %%, time-domain oblique path %.12g %%\n", none, oblique180);
  CHECK(oblique180 == Approx(ObliqueMeanMsi(180.0)).epsilon(1e-12));
  // The oblique path's heave and pitch at 180 deg equal the head-sea path's to 1e-14 of their peaks
  // (verification_oblique_periodic_head_seas); the MSI then goes through the oblique point response, whose
  // Simpson rule interpolates the RAOs linearly in the wave frequency where the head-sea one interpolates in
  // the encounter frequency (evaluation/oblique_point_response.h). Between 20 frequencies 0.12 rad/s apart
  // the two interpolations differ by O(Δω²) of the RAOs' curvature, a few 1e-3 of the MSI.
  constexpr double kOtherPointResponseTol = 5e-3;
  CHECK(oblique180 == Approx(none).epsilon(kOtherPointResponseTol));
  auto e = eval::MakeMsiEvaluator(Basis(), kNames, Options({180.0, 150.0}));
  CHECK(e->ObjectiveMethod().find("time-domain strip method") != std::string::npos);
  CHECK(e->ObjectiveLabel() == "mean MSI over 2 seas, 2 headings [%]");
  CHECK(eval::MakeMsiEvaluator(Basis(), kNames, Options({180.0}))->ObjectiveMethod().find("head seas") == 0);
}

TEST_CASE("with solver.method strip_theory_stf the headings go to the oblique-sea strip theory with Cs",
          "[verification][oblique]") {
  eval::DesignBasis b = Basis();
  b.solver.rao.method = sk::RaoSolverOptions::Method::kStripTheory;
  auto e = eval::MakeMsiEvaluator(b, kNames, Options({180.0, 150.0}, {1.0, 0.0}));
  CHECK(e->ObjectiveMethod().find("oblique-sea strip theory") != std::string::npos);
  const opt::EvalResult r = e->Evaluate(kX);
  INFO(r.error);
  REQUIRE(r.produced);
  // The design's Cs reaches the oblique-sea strip theory, and the objective is its point response here.
  const eval::DesignCase d = eval::BuildTrialDesign(b, eval::TrialFields(kNames), kX);
  const sk::ObliqueStripResult stf = eval::SolveObliqueDesign(d, d.speed_m_s, eval::SeaFrequencies(d), {180.0},
                                                              eval::DefaultRollRadiusOfGyration(d.hull));
  CHECK(stf.waves.front().cs_damping.norm() > 0.0);
  const double direct = ObliqueMeanMsi(180.0, b);
  std::printf("180 deg by STF with Cs: objective %.12g %%, point response %.12g %%\n", r.objective, direct);
  constexpr double kRoundingTol = 1e-12;
  CHECK(r.objective == Approx(direct).epsilon(kRoundingTol));
}

TEST_CASE("bad headings and weights are refused", "[verification][oblique]") {
  auto refuses = [](const eval::MsiObjectiveOptions& o, const char* what) {
    std::string err;
    CHECK_FALSE(o.IsValid(&err));
    INFO(err);
    CHECK(err.find(what) != std::string::npos);
    CHECK_THROWS_AS(eval::MakeMsiEvaluator(Basis(), kNames, o), std::invalid_argument);
  };
  refuses(Options({180.0, 360.0}), "headings_deg[1] = 360");
  refuses(Options({150.0, 150.0}), "given twice");
  refuses(Options({180.0, 150.0}, {1.0, -1.0}), "heading_weights[1] = -1");
  refuses(Options({180.0, 150.0}, {0.0, 0.0}), "at least one weight must be > 0");
  refuses(Options({180.0, 150.0}, {1.0}), "1 weights for 2 headings");
  eval::MsiObjectiveOptions pe = Options({150.0});
  pe.measure = eval::MsiObjectiveOptions::Measure::kEffectivePower;
  refuses(pe, "applies to the measures msi and rms_accel only");
}
