// FirstYamlDifference: names the first differing key with both values, or "" for equal trees (numbers compared
// as emitted text, so a tree built in memory equals the same tree read back from a file).
#include <catch2/catch.hpp>

#include "io/config/yaml_difference.h"

using hullopt::io::FirstYamlDifference;

TEST_CASE("first difference between two YAML trees", "[yaml]") {
  const YAML::Node a = YAML::Load("solver: { Cs: 0.065, sections: 40 }\nseas: [{ Hs_m: 1.0 }, { Hs_m: 3.0 }]\n");
  YAML::Node built;
  built["solver"]["Cs"] = 0.065;
  built["solver"]["sections"] = 40;
  built["seas"].push_back(YAML::Load("{ Hs_m: 1.0 }"));
  built["seas"].push_back(YAML::Load("{ Hs_m: 3.0 }"));
  CHECK(FirstYamlDifference(a, built) == "");

  YAML::Node added = YAML::Clone(a);
  added["solver"]["sectional_force"] = "momentum";
  CHECK(FirstYamlDifference(a, added) == "key 'solver.sectional_force': absent before, now 'momentum'");
  CHECK(FirstYamlDifference(added, a) == "key 'solver.sectional_force': 'momentum' before, absent now");

  YAML::Node changed = YAML::Clone(a);
  changed["seas"][1]["Hs_m"] = 2.5;
  CHECK(FirstYamlDifference(a, changed) == "key 'seas[1].Hs_m': '3.0' before, now '2.5'");

  YAML::Node longer = YAML::Clone(a);
  longer["seas"].push_back(YAML::Load("{ Hs_m: 4.0 }"));
  CHECK_THAT(FirstYamlDifference(a, longer), Catch::StartsWith("key 'seas': "));
}
