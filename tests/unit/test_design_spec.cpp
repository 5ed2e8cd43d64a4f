// One design builder: a config is read and checked whole (every block) before anything is built, and
// eval::BuildDesign then generates the hull and solves the calm-water attitude once. The counts of hulls
// built and calm-water attitudes solved (eval::BuildCounts) show what was computed; a design built from typed
// values is the one the config reader builds from the same values, to the bit.
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>

#include "evaluation/design_spec.h"
#include "io/config/design_config.h"
#include "io/config/design_defaults.h"
#include "io/config/motion_config.h"
#include "io/config/seas_config.h"
#include "io/formats/input_error.h"
#include "support/npl5b_config.h"

using namespace hullopt;

namespace {

// A catamaran at 40 kn with the running attitude solved in calm water (solver.steady_flow: on); coarse strips
// keep the solves cheap.
const std::string kConfig =
    std::string(test::kNpl5bDesignYaml) +
    "solver: { Cs: 0.065, sections: 12, panels: 6, steady_flow: on, adaptive_grid: off }\n";

io::YamlMap Root(const YAML::Node& n) {
  return io::YamlMap(n, "", "design.yaml", YAML::Node(YAML::NodeType::Map));
}

bool Same(const eval::DesignBuildCounts& a, const eval::DesignBuildCounts& b) {
  return a.hulls == b.hulls && a.calm_water_solves == b.calm_water_solves;
}

}  // namespace

TEST_CASE("an error in the last block of a design config is refused before any hull or calm water") {
  const eval::DesignBuildCounts before = eval::BuildCounts();
  SECTION("a misspelt key in the mass block, read last") {
    const YAML::Node cfg = YAML::Load(kConfig + "mass: { kyy_over_l: 0.25 }\n");
    io::YamlMap root = Root(cfg);
    try {
      io::ParseDesign(root, "design.yaml", "design");
      FAIL("the misspelt key was accepted");
    } catch (const io::InputError& e) {
      CHECK_THAT(e.what(), Catch::Contains("mass.kyy_over_l"));
    }
  }
  SECTION("an unknown block after the design's, refused by Finish before the build") {
    const YAML::Node cfg = YAML::Load(kConfig + "mass: { kyy_over_L: 0.25 }\nseaz: []\n");
    io::YamlMap root = Root(cfg);
    io::ParsedDesign parsed = io::ParseDesign(root, "design.yaml", "design");
    CHECK_THROWS_WITH(root.Finish(), Catch::Contains("seaz"));
  }
  SECTION("a sea block with a bad value, after the design's blocks") {
    const YAML::Node cfg = YAML::Load(kConfig + "seas: [ { Hs_m: -1, Tz_s: 7 } ]\n");
    io::YamlMap root = Root(cfg);
    io::ParseDesign(root, "design.yaml", "design");
    CHECK_THROWS_AS(io::ReadSeas(root), io::InputError);
  }
  SECTION("a mass rule that needs the hull waits for the build: the parse alone builds nothing") {
    // An LCG far off the hull is a build-time refusal; parsing the config must not find it (nothing built).
    const YAML::Node cfg = YAML::Load(kConfig + "mass: { lcg_m_from_ap: 1.0e6 }\n");
    io::YamlMap root = Root(cfg);
    io::ParsedDesign parsed = io::ParseDesign(root, "design.yaml", "design");
    root.Finish();
    CHECK(Same(eval::BuildCounts(), before));
    CHECK_THROWS_WITH(io::BuildParsedDesign(parsed), Catch::Contains("mass.lcg_m_from_ap"));
    return;
  }
  CHECK(Same(eval::BuildCounts(), before));
}

TEST_CASE("a design is built once: one hull, one calm-water attitude") {
  const YAML::Node cfg = YAML::Load(kConfig);
  io::YamlMap root = Root(cfg);
  io::ParsedDesign parsed = io::ParseDesign(root, "design.yaml", "design");
  root.Finish();
  const eval::DesignBuildCounts before = eval::BuildCounts();
  const eval::DesignCase d = io::BuildParsedDesign(parsed);
  const eval::DesignBuildCounts after = eval::BuildCounts();
  CHECK(after.hulls - before.hulls == 1);
  CHECK(after.calm_water_solves - before.calm_water_solves == 1);
  CHECK(d.solver.steady_flow);
  CHECK_FALSE(d.attitude.IsEvenKeel());  // 40 kn: the solved attitude is not even keel
  // The mass defaults the hull gave are recorded where the keys stand in the resolved config.
  const YAML::Node mass = root.resolved()["mass"];
  std::vector<std::string> keys;
  for (const auto& kv : mass) keys.push_back(kv.first.as<std::string>());
  CHECK(keys ==
        std::vector<std::string>{"mass_kg", "lcg_m_from_ap", "kyy_m", "kg_m", "accept_mass_mismatch"});
  CHECK(mass["mass_kg"].as<double>() == d.hydrostatics.displacement_kg);
  CHECK(mass["kyy_m"].as<double>() == 0.25 * d.hydrostatics.L_m);
}

TEST_CASE("the default frequency grid builds the hull at rest only, without a calm-water attitude") {
  YAML::Node cfg = YAML::Load(kConfig);  // no solver.frequencies
  io::YamlMap root = Root(cfg);
  const eval::DesignBuildCounts before = eval::BuildCounts();
  std::vector<std::string> notes;
  io::FillDesignDefaults(root, &notes);
  const eval::DesignBuildCounts after = eval::BuildCounts();
  CHECK(cfg["solver"]["frequencies"]);
  CHECK(after.hulls - before.hulls == 1);
  CHECK(after.calm_water_solves == before.calm_water_solves);
}

TEST_CASE("a design from typed values is the config reader's design of the same values, to the bit") {
  const YAML::Node cfg = YAML::Load(kConfig + "mass: { kyy_over_L: 0.26, kg_m: 4.0 }\n");
  io::YamlMap root = Root(cfg);
  const eval::DesignCase from_config = io::LoadDesignCase(root, "design.yaml", "design");

  eval::DesignSpec spec;
  spec.source = "typed";
  spec.hull.variables.type = hull::HullType::kCatamaran;
  spec.hull.variables.section_style = hull::SectionStyle::kRoundBilge;
  spec.hull.variables.displacement_t = 1000;
  spec.hull.variables.L_over_B = 11.0;
  spec.hull.variables.B_over_T = 2.0;
  spec.hull.variables.Cb = 0.40;
  spec.hull.variables.Cp = 0.69;
  spec.hull.variables.Cwp = 0.76;
  spec.hull.variables.LCB_pct_L = -6.4;
  spec.hull.variables.LCF_pct_L = -8.3;
  spec.hull.variables.transom_immersion = 0.3;
  spec.hull.variables.spacing_over_L = 0.25;
  spec.speed.unit = eval::SpeedOptions::Unit::kKnots;
  spec.speed.value = 40;
  spec.solver.rao.motion.damping_cs = 0.065;
  spec.solver.rao.sections = 12;
  spec.solver.rao.panels = 6;
  spec.solver.steady_flow = true;
  spec.solver.grid.enabled = false;
  spec.mass.kyy_over_L = 0.26;
  spec.mass.kg_m = 4.0;
  const eval::DesignCase typed = eval::BuildDesign(spec);

  CHECK(typed.speed_m_s == from_config.speed_m_s);
  CHECK(typed.hydrostatics.displacement_kg == from_config.hydrostatics.displacement_kg);
  CHECK(typed.mass.kyy_m == from_config.mass.kyy_m);
  CHECK(typed.mass.kg_m == from_config.mass.kg_m);
  CHECK(typed.attitude.sinkage_m == from_config.attitude.sinkage_m);
  CHECK(typed.attitude.trim_deg == from_config.attitude.trim_deg);
  const std::vector<double> omega = {0.8, 1.2};
  const sk::RaoTable a = eval::ComputeDesignRaos(typed, omega),
                     b = eval::ComputeDesignRaos(from_config, omega);
  REQUIRE(a.heave.size() == b.heave.size());
  for (std::size_t i = 0; i < a.heave.size(); ++i) {
    CHECK(a.heave[i] == b.heave[i]);
    CHECK(a.pitch[i] == b.pitch[i]);
  }
}

TEST_CASE("the solver settings' own defaults are a config's without a solver block") {
  // The typed routes (Python's design()) start from eval::SolverSettings{}; a config without the keys reads
  // the same values, so the two give the same design.
  const YAML::Node cfg = YAML::Load("solver: {}\n");
  io::YamlMap root = Root(cfg);
  io::YamlMap s = root.Map("solver");
  const eval::SolverSettings read = io::ParseSolverConfig(s, false), typed;
  CHECK(read.rao.method == typed.rao.method);
  CHECK(read.rao.sections == typed.rao.sections);
  CHECK(read.rao.panels == typed.rao.panels);
  CHECK(read.cs() == typed.cs());
  CHECK(read.rao.path == typed.rao.path);
  CHECK(read.rao.interaction == typed.rao.interaction);
  CHECK(read.rao.layout == typed.rao.layout);
  CHECK(read.rao.marching.hydrodynamic_fraction == typed.rao.marching.hydrodynamic_fraction);
  CHECK(read.sectional_force == typed.sectional_force);
  CHECK(read.body_potential == typed.body_potential);
  CHECK(read.steady_flow == typed.steady_flow);
  CHECK(read.grid.enabled == typed.grid.enabled);
  CHECK(read.grid.max_passes == typed.grid.max_passes);
  CHECK(read.grid.max_frequencies == typed.grid.max_frequencies);
}
