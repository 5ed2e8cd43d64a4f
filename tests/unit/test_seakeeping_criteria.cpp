// Seakeeping criteria as data (io/formats/criteria_csv.h) and the verdict (evaluation/seakeeping_criteria.h): the
// shipped NORDFORSK set holds the published limits, malformed files are refused with the line, and a verdict
// marks each criterion by its value against its limit.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>

#include "evaluation/seakeeping_criteria.h"
#include "io/formats/criteria_csv.h"
#include "io/formats/input_error.h"
#include "seakeeping/motions/encounter_frequency.h"

using namespace hullopt;

TEST_CASE("the shipped criteria file holds the NORDFORSK 1987 limits for fast small craft", "[criteria]") {
  const eval::CriteriaSet& set = io::DefaultCriteria();
  REQUIRE(set.criteria.size() == 6);
  auto find = [&](const std::string& name) -> const eval::SeakeepingCriterion& {
    for (const auto& c : set.criteria)
      if (c.name == name) return c;
    FAIL("no criterion " << name);
    return set.criteria.front();
  };
  // Published values (NORDFORSK 1987 as tabulated by Tezdogan et al. 2014): 0.65 g rms at the FP, 0.275 g at
  // the bridge, 0.05 g for transit passengers, slamming 0.03, deck wetness 0.05.
  CHECK(find("fp_vertical_acceleration").limit == 0.65);
  CHECK(find("fp_vertical_acceleration").location == "fp");
  CHECK(find("bridge_vertical_acceleration").limit == 0.275);
  CHECK(find("passenger_vertical_acceleration").limit == 0.05);
  CHECK(find("motion_sickness").limit == 10.0);
  CHECK(find("slamming").quantity == eval::CriterionQuantity::kSlammingProbability);
  CHECK(find("slamming").limit == 0.03);
  CHECK(find("deck_wetness").limit == 0.05);
  for (const auto& c : set.criteria) CHECK_FALSE(c.source.empty());
}

TEST_CASE("criteria files: a wrong unit, quantity, location or header is refused with its line", "[criteria]") {
  const std::string head = "# comment\ncriterion,quantity,location,limit,unit,source\n";
  auto refuses = [&](const std::string& row, const std::string& words) {
    try {
      io::ParseCriteriaCsv(head + row, "c.csv", "t");
      FAIL("accepted: " << row);
    } catch (const io::InputError& e) {
      const std::string what = e.what();
      INFO(what);
      CHECK(what.find("c.csv:3") != std::string::npos);
      CHECK(what.find(words) != std::string::npos);
    }
  };
  refuses("a,rms_vertical_acceleration,fp,6.4,m/s2,src\n", "unit 'm/s2'");
  refuses("a,heave,fp,1,m,src\n", "quantity 'heave'");
  refuses("a,slamming_probability,lcg,0.03,-,src\n", "fp or x_over_L");
  refuses("a,slamming_probability,x_over_L=1.5,0.03,-,src\n", "within 0..1");
  refuses("a,msi,fp,10,%,src\n", "passenger position");
  refuses("a,deck_wetness_probability,fp,2,-,src\n", "<= 1");
  CHECK_THROWS_WITH(io::ParseCriteriaCsv(head + "a,msi,mean,10,%,src\na,msi,lcg,10,%,src\n", "c.csv", "t"),
                    Catch::Contains("c.csv:4") && Catch::Contains("given twice"));
  CHECK_THROWS_AS(io::ParseCriteriaCsv("name,limit\n", "c.csv", "t"), io::InputError);
  const auto ok = io::ParseCriteriaCsv(head + "a,msi,mean,10,%,\"x, y\"\n", "c.csv", "t");
  REQUIRE(ok.criteria.size() == 1);
  CHECK(ok.criteria[0].source == "x, y");
}

TEST_CASE("verdict: values against limits, margins, and the limiting Hs", "[criteria]") {
  // A hand-made evaluation: two seas, the mean MSI 4 % then 14 %; a 10 % limit holds in the first (margin
  // +60 %) and fails in the second (-40 %).
  sk::RaoTable rao;
  rao.speed_m_s = 10.0;
  for (int i = 0; i < 40; ++i) {
    const double w = 0.2 + 0.1 * i;
    rao.omega_rad_s.push_back(w);
    rao.omega_e_rad_s.push_back(sk::HeadSeaEncounterFrequency(w, 10.0, 9.81));
    rao.heave.push_back({0.0, 0.0});
    rao.pitch.push_back({0.0, 0.0});
  }
  sk::HullExtent hull{20.0, 20.0};
  sk::DesignEvaluation ev;
  for (double hs : {1.0, 2.0}) {
    sk::SeaEvaluation s;
    s.sea = sk::SeaState::JonswapTz(hs, 6.0);
    s.Tz_s = 6.0;
    s.mean.position = "mean";
    s.mean.msi_pct = hs == 1.0 ? 4.0 : 14.0;
    ev.seas.push_back(s);
  }
  eval::CriteriaSet set;
  set.title = "test";
  eval::SeakeepingCriterion msi;
  msi.name = "msi";
  msi.quantity = eval::CriterionQuantity::kMsi;
  msi.location = "mean";
  msi.limit = 10.0;
  eval::SeakeepingCriterion wet;
  wet.name = "wet";
  wet.quantity = eval::CriterionQuantity::kDeckWetnessProbability;
  wet.location = "fp";
  wet.limit = 0.05;
  set.criteria = {msi, wet};
  // Wall-sided bow, freeboard 1 m. The ship does not move (zero RAOs): r = −ζ, m0_r = (Hs/4)² as far as the
  // table covers the spectrum, so P_w = exp(−1/(2 (Hs/4)²)) = exp(−8/Hs²).
  eval::BowGeometry g;
  g.x_over_L = {0.0, 1.0};
  g.keel_z_m = {0.0, 0.0};
  g.deck_z_m = {3.0, 3.0};
  g.waterline_z_m = 2.0;
  g.length_m = 40.0;
  const eval::SeakeepingVerdict v = eval::JudgeDesign(rao, hull, ev, g, set);
  REQUIRE(v.seas.size() == 2);
  constexpr double kRoundOff = 1e-12;
  CHECK(v.seas[0].checks[0].met);
  CHECK(v.seas[0].checks[0].margin == Approx(0.6).epsilon(kRoundOff));
  CHECK_FALSE(v.seas[1].checks[0].met);
  CHECK(v.seas[1].checks[0].margin == Approx(-0.4).epsilon(kRoundOff));
  // The table (ω 0.2..4.1 rad/s) leaves a little of each spectrum out: 1 % on the probability's exponent.
  constexpr double kTruncationTolerance = 0.01;
  CHECK(std::log(v.seas[0].checks[1].value) == Approx(-8.0).epsilon(kTruncationTolerance));
  CHECK(std::log(v.seas[1].checks[1].value) == Approx(-2.0).epsilon(kTruncationTolerance));
  CHECK(v.seas[0].checks[1].met);         // exp(−8) = 3e-4
  CHECK_FALSE(v.seas[1].checks[1].met);   // exp(−2) = 0.135
  CHECK(v.limiting_Hs_m == 1.0);
  // Without a hull geometry the probability is not judged, and does not fail the sea.
  const eval::SeakeepingVerdict nv = eval::JudgeDesign(rao, hull, ev, eval::BowGeometry{}, set);
  CHECK_FALSE(nv.seas[0].checks[1].judged);
  CHECK(nv.seas[0].all_met);
  // An unknown position is refused.
  set.criteria[0].location = "bridge";
  CHECK_THROWS_AS(eval::JudgeDesign(rao, hull, ev, g, set), std::invalid_argument);
}
