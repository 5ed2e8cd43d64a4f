// A campaign's trial design set field by field is the design a config holding the same values describes: same
// hull, mass, speed and RAOs to the bit (the reference is the config reader, a separate path), and the same
// refusal wording for a value the rules refuse.
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>

#include "evaluation/trial_design.h"
#include "io/config/design_config.h"
#include "support/npl5b_config.h"

using namespace hullopt;

namespace {
const std::string kBase =
    std::string(test::kNpl5bDesignYaml) + "solver: { Cs: 0.065, sections: 12, panels: 6 }\n";

eval::DesignBasis Basis() {
  io::YamlMap root(YAML::Load(kBase), "", "base.yaml", YAML::Node(YAML::NodeType::Map));
  io::DesignConfig c;
  io::LoadDesignCase(root, "base.yaml", "design", true, &c);
  return io::TrialBasis(c, "base.yaml");
}

// The same design through a config: the values written into the YAML text, the campaign's mass rule after.
eval::DesignCase FromConfig(const std::vector<std::string>& names, const std::vector<double>& x) {
  YAML::Node cfg = YAML::Load(kBase);
  for (std::size_t i = 0; i < names.size(); ++i) cfg["hull"]["parametric"][names[i]] = x[i];
  io::YamlMap root(cfg, "", "base.yaml", YAML::Node(YAML::NodeType::Map));
  eval::DesignCase d = io::LoadDesignCase(root, "base.yaml", "design");
  d.mass.mass_kg = d.hydrostatics.displacement_kg;
  d.mass.lcg_m_from_ap = d.hydrostatics.lcb_m_from_ap;
  d.mass.kyy_m = 0.25 * d.hydrostatics.L_m;
  d.mass.kg_m = d.hydrostatics.T_m;
  d.hydrostatics = hull::ComputeHydrostatics(d.hull, d.water.rho_kg_m3, d.mass.kg_m);
  return d;
}
}  // namespace

TEST_CASE("a trial design equals the config with its values, to the bit", "[evaluation]") {
  const std::vector<std::string> names = {"L_over_B", "B_over_T", "Cp", "LCF_pct_L"};
  const std::vector<double> x = {9.123456789012345, 1.7, 0.6543210987654321, -5.5};
  const eval::DesignCase a = eval::BuildTrialDesign(Basis(), eval::TrialFields(names), x);
  const eval::DesignCase b = FromConfig(names, x);
  CHECK(a.hydrostatics.L_m == b.hydrostatics.L_m);
  CHECK(a.hydrostatics.gm_l_m == b.hydrostatics.gm_l_m);
  CHECK(a.mass.kyy_m == b.mass.kyy_m);
  CHECK(a.speed_m_s == b.speed_m_s);
  CHECK(a.input_warnings == b.input_warnings);
  const std::vector<double> w = {0.8, 1.2, 1.6};
  const sk::RaoTable ra = eval::ComputeDesignRaos(a, w), rb = eval::ComputeDesignRaos(b, w);
  REQUIRE(ra.heave.size() == rb.heave.size());
  for (std::size_t i = 0; i < w.size(); ++i) {
    CHECK(ra.heave[i] == rb.heave[i]);
    CHECK(ra.pitch[i] == rb.pitch[i]);
  }
  CHECK(ra.warnings == rb.warnings);
}

TEST_CASE("a trial value the rules refuse is worded as the config reader words it", "[evaluation][errors]") {
  const std::vector<std::string> names = {"Cp"};
  std::string expected;
  try {
    FromConfig(names, {1.2});
  } catch (const io::InputError& e) {
    expected = e.what();
  }
  REQUIRE(expected.find("key 'hull.parametric.Cp'") != std::string::npos);
  CHECK_THROWS_WITH(eval::BuildTrialDesign(Basis(), eval::TrialFields(names), {1.2}), expected);
}
