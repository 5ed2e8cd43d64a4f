// Campaign definitions: every bad input is refused by IsValid (before any evaluation) with a message naming
// the item, the value and the rule; constraint keys parse into quantity and kind; the YAML block is read
// strictly.
#include <catch2/catch.hpp>

#include "io/config/campaign_config.h"
#include "optimizer/campaign.h"

using hullopt::opt::CampaignDefinition;
using hullopt::opt::Constraint;

namespace {
CampaignDefinition Good() {
  CampaignDefinition d;
  d.variables = {{"L_over_B", 8, 16, 11}, {"Cp", 0.55, 0.75, 0.69}};
  d.constraints = {{"L_max_m", "L_m", Constraint::Kind::kMax, 75.0}};
  d.known_quantities = {"L_m", "B_overall_m", "Cvp"};
  d.known_variables = {"L_over_B", "B_over_T", "Cp", "Cb"};
  return d;
}
std::string Error(const CampaignDefinition& d) {
  std::string e;
  CHECK_FALSE(d.IsValid(&e));
  return e;
}
}  // namespace

TEST_CASE("a good campaign is valid", "[campaign]") {
  std::string e;
  CHECK(Good().IsValid(&e));
}

TEST_CASE("constraint keys name quantity, kind and unit", "[campaign]") {
  std::string q;
  Constraint::Kind k;
  REQUIRE(hullopt::opt::ParseConstraintKey("L_max_m", &q, &k));
  CHECK(q == "L_m");
  CHECK(k == Constraint::Kind::kMax);
  REQUIRE(hullopt::opt::ParseConstraintKey("Cvp_min", &q, &k));
  CHECK(q == "Cvp");
  CHECK(k == Constraint::Kind::kMin);
  REQUIRE(hullopt::opt::ParseConstraintKey("GM_T_min_m", &q, &k));
  CHECK(q == "GM_T_m");
  CHECK_FALSE(hullopt::opt::ParseConstraintKey("L_m", &q, &k));
  CHECK_FALSE(hullopt::opt::ParseConstraintKey("max", &q, &k));
}

TEST_CASE("bad campaigns are refused with clear messages", "[campaign][bad-input]") {
  auto d = Good();
  d.variables[0].name = "L_over_Q";
  CHECK_THAT(Error(d), Catch::Contains("unknown design variable 'L_over_Q'"));

  d = Good();
  d.variables[1].lower = 0.8;
  CHECK_THAT(Error(d), Catch::Contains("variables.Cp") && Catch::Contains("inverted"));

  d = Good();
  d.variables[1].lower = d.variables[1].upper = 0.69;
  CHECK_THAT(Error(d), Catch::Contains("empty"));

  d = Good();
  d.algorithm = "LN_COBYLAA";
  CHECK_THAT(Error(d),
             Catch::Contains("'LN_COBYLAA' is not an NLopt algorithm") && Catch::Contains("LN_BOBYQA"));

  d = Good();
  d.algorithm = "LD_MMA";
  CHECK_THAT(Error(d), Catch::Contains("needs gradients"));

  d = Good();
  d.algorithm = "AUGLAG";
  CHECK_THAT(Error(d), Catch::Contains("subsidiary"));

  d = Good();
  d.variables[0].start = 20;
  CHECK_THAT(Error(d), Catch::Contains("start value 20 is outside the bounds [8, 16]"));

  d = Good();
  d.constraints.push_back({"L_min_m", "L_m", Constraint::Kind::kMin, 80.0});
  CHECK_THAT(Error(d), Catch::Contains("L_min_m = 80") && Catch::Contains("L_max_m = 75") &&
                           Catch::Contains("contradict"));

  d = Good();
  d.constraints.push_back({"L_over_B_max", "L_over_B", Constraint::Kind::kMax, 7.0});
  CHECK_THAT(Error(d), Catch::Contains("contradicts the bounds of 'L_over_B'"));

  d = Good();
  d.constraints.push_back({"L_over_B_max", "L_over_B", Constraint::Kind::kMax, 10.0});
  CHECK_THAT(Error(d), Catch::Contains("violates it"));  // start 11 > 10 with a local algorithm
  d.algorithm = "GN_ISRES";
  std::string e;
  CHECK(d.IsValid(&e));  // a global algorithm does not need a feasible start

  d = Good();
  d.constraints.push_back({"GM_T_min_m", "GM_T_m", Constraint::Kind::kMin, 1.0});
  CHECK_THAT(Error(d), Catch::Contains("unknown quantity 'GM_T_m'"));

  d = Good();
  d.stopping.max_evaluations = 0;
  CHECK_THAT(Error(d), Catch::Contains("max_evaluations"));

  d = Good();
  d.starts = 0;
  CHECK_THAT(Error(d), Catch::Contains("starts"));
}

TEST_CASE("the optimize block is read strictly with line numbers", "[campaign][yaml]") {
  using hullopt::io::InputError;
  using hullopt::io::YamlMap;
  auto read = [](const std::string& text) {
    const YAML::Node raw = YAML::Load(text);
    YamlMap root(raw, "", "c.yaml", YAML::Node(YAML::NodeType::Map));
    std::optional<YamlMap> block;
    auto cfg = hullopt::io::ReadCampaignConfig(root, raw, hullopt::io::CampaignCommand::kOptimize, &block);
    block->Finish();
    return cfg;
  };
  const auto cfg = read(
      "hull:\n  parametric: { L_over_B: 11.0, Cp: 0.69 }\n"
      "optimize:\n  algorithm: LN_BOBYQA\n  variables: { L_over_B: [8, 16], Cp: [0.55, 0.75] }\n"
      "  start: { Cp: 0.6 }\n  constraints: { L_max_m: 75 }\n");
  REQUIRE(cfg.definition.variables.size() == 2);
  CHECK(cfg.definition.variables[0].start == 11.0);
  CHECK(cfg.start_source[0] == "hull.parametric");
  CHECK(cfg.definition.variables[1].start == 0.6);
  CHECK(cfg.definition.constraints[0].quantity == "L_m");
  CHECK(cfg.definition.algorithm == "LN_BOBYQA");

  CHECK_THROWS_WITH(read("optimize:\n  variables: { x: [1, 2, 3] }\n  start: { x: 1 }\n"),
                    Catch::Contains("c.yaml:2") && Catch::Contains("[lower, upper]"));
  CHECK_THROWS_WITH(read("optimize:\n  variables: { x: [1, 2] }\n"), Catch::Contains("has no base value"));
  CHECK_THROWS_WITH(read("optimize:\n  variables: { x: [1, 2] }\n  start: { x: 1, y: 2 }\n"),
                    Catch::Contains("'optimize.start.y'") && Catch::Contains("not a free variable"));
  CHECK_THROWS_WITH(
      read("optimize:\n  variables: { x: [1, 2] }\n  start: { x: 1 }\n  constraints: { L_m: 3 }\n"),
      Catch::Contains("_max or <quantity>_min"));
  CHECK_THROWS_WITH(read("optimize:\n  variables: { x: [1, 2] }\n  start: { x: 1 }\n  max_evals: 3\n"),
                    Catch::Contains("unknown key 'optimize.max_evals'"));
}
