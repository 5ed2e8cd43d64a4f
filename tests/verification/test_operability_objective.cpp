// The campaign's operability objectives against the ordinary MSI objective of the same designs: a one-cell
// scatter diagram whose cell is the campaign's sea gives the MSI objective exactly (the cell goes through
// EvaluateOperability, the sea through the MSI objective's own EvaluateDesign call); a two-cell diagram gives the
// probability-weighted mean of the MSI objective's per-sea values; the downtime objective counts the cells whose
// MSI exceeds the limit.
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/formats/input_error.h"
#include "io/config/msi_objective_config.h"
#include "io/config/yaml_map.h"

namespace {

using hullopt::io::YamlMap;

// The default campaign's catamaran at a low strip resolution (the comparison is of two paths through the same
// RAOs, not of the RAOs).
const char* const kShip = R"(
hull:
  parametric: { type: catamaran, section_style: round_bilge, displacement_t: 1000, L_over_B: 11.0, B_over_T: 2.0,
                Cb: 0.40, Cp: 0.69, Cwp: 0.76, LCB_pct_L: -6.4, LCF_pct_L: -8.3, transom_immersion: 0.3,
                spacing_over_L: 0.25 }
water: { rho_kg_m3: 1025, g_m_s2: 9.81 }
speed: { kn: 40 }
solver: { Cs: 0.065, sections: 10, panels: 6 }
)";

hullopt::opt::CampaignDefinition Campaign() {
  hullopt::opt::CampaignDefinition c;
  c.variables = {{"L_over_B", 8.0, 16.0}, {"B_over_T", 1.4, 2.6}};
  return c;
}

std::string WriteCsv(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path) << text;
  return path;
}

std::unique_ptr<hullopt::opt::Evaluator> Make(const std::string& text) {
  YamlMap root(YAML::Load(std::string(kShip) + text), "", "test.yaml", YAML::Node(YAML::NodeType::Map));
  YamlMap block = root.Map("optimize");
  YamlMap objective = block.MapOrEmpty("objective");
  auto e = hullopt::io::ReadMsiObjective(root, objective, Campaign());
  block.Finish();
  return e;
}

const std::vector<std::vector<double>> kDesigns = {{11.0, 2.0}, {13.5, 1.7}, {9.0, 2.5}};

}  // namespace

TEST_CASE("one-cell scatter diagram: the scatter_msi objective is the msi objective of that sea, exactly") {
  const std::string one = WriteCsv("hullopt_test_one_cell.csv", "Hs_m\\Tz_s,7.5\n3.0,1\n");
  for (const char* position : {"mean", "forward", "transom"}) {
    const std::string pos = position;
    auto msi = Make("seas: [ { spectrum: jonswap, Hs_m: 3.0, Tz_s: 7.5, gamma: 3.3 } ]\n"
                    "optimize: { objective: { measure: msi, position: " + pos + " } }\n");
    auto op = Make("operability: { scatter_csv: " + one + ", criteria: [ { msi_max_pct: 20 } ] }\n"
                   "optimize: { objective: { measure: scatter_msi, position: " + pos + " } }\n");
    REQUIRE(op->SeaNames() == msi->SeaNames());  // msi_pct_Hs3_Tz7.5 either way
    for (const auto& x : kDesigns) {
      const auto a = msi->Evaluate(x), b = op->Evaluate(x);
      REQUIRE(a.produced);
      REQUIRE(b.produced);
      CHECK(b.objective == a.objective);  // bit for bit: p = 1 weights one cell, as weight 1 weights one sea
      CHECK(b.sea_values == a.sea_values);
      CHECK(b.quantities == a.quantities);
      CHECK(op->ObjectiveImplied(x, b.sea_values) == b.objective);
    }
  }
}

TEST_CASE("two-cell scatter diagram: probability-weighted MSI and downtime against the two-sea msi objective") {
  const std::string two = WriteCsv("hullopt_test_two_cells.csv", "Hs_m\\Tz_s,5.5,7.5\n1.0,0.7,\n3.0,,0.3\n");
  auto msi = Make("seas: [ { spectrum: jonswap, Hs_m: 1.0, Tz_s: 5.5 }, { spectrum: jonswap, Hs_m: 3.0, Tz_s: 7.5 } ]\n"
                  "optimize: { objective: { measure: msi } }\n");
  // MSI 20 % lies between the two cells' MSI for these designs (about 5 % in 1 m, 50 % in 3 m seas).
  const std::string op_block = "operability: { scatter_csv: " + two +
                               ", criteria: [ { msi_max_pct: 20, name: comfort }, { msi_max_pct: 99 } ] }\n";
  auto scatter = Make(op_block + "optimize: { objective: { measure: scatter_msi } }\n");
  auto down = Make(op_block + "optimize: { objective: { measure: downtime_pct, criterion: comfort } }\n");
  auto down_all = Make(op_block + "optimize: { objective: { measure: downtime_pct } }\n");
  for (const auto& x : kDesigns) {
    const auto a = msi->Evaluate(x), b = scatter->Evaluate(x), c = down->Evaluate(x), d = down_all->Evaluate(x);
    REQUIRE(a.sea_values.size() == 2);
    REQUIRE(b.sea_values == a.sea_values);
    // Σ p MSI / Σ p, summed in another order than the evaluator's: a few ulps (1e-14 relative).
    CHECK_THAT(b.objective, Catch::Matchers::WithinRel((0.7 * a.sea_values[0] + 0.3 * a.sea_values[1]) / 1.0, 1e-14));
    REQUIRE(a.sea_values[0] <= 20.0);
    REQUIRE(a.sea_values[1] > 20.0);
    CHECK_THAT(c.objective, Catch::Matchers::WithinAbs(30.0, 1e-12));  // the 3 m cell, 30 % of the time
    CHECK_THAT(d.objective, Catch::Matchers::WithinAbs(30.0, 1e-12));  // MSI <= 99 % is met in both
    CHECK(std::isnan(down->ObjectiveImplied(x, c.sea_values)));        // checked by the spot recomputation
  }
}

TEST_CASE("operability objective: bad keys are refused naming the key") {
  const std::string one = WriteCsv("hullopt_test_one_cell_b.csv", "Hs_m\\Tz_s,7.5\n3.0,1\n");
  const std::string block = "operability: { scatter_csv: " + one + ", criteria: [ { msi_max_pct: 20 } ] }\n";
  auto refused = [&](const std::string& text, const std::string& key) {
    try {
      Make(text);
    } catch (const hullopt::io::InputError& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find(key) != std::string::npos);
      return;
    }
    FAIL("not refused: " + text);
  };
  refused("seas: [ { Hs_m: 3.0, Tz_s: 7.5 } ]\noptimize: { objective: { measure: scatter_msi } }\n",
          "'optimize.objective.measure'");
  refused(block + "optimize: { objective: { measure: downtime_pct, criterion: nosuch } }\n",
          "'optimize.objective.criterion'");
  refused(block + "optimize: { objective: { measure: scatter_msi, criterion: all } }\n",
          "'optimize.objective.criterion'");
  refused(block + "optimize: { objective: { measure: scatter_msi, sea_weights: [1] } }\n",
          "'optimize.objective.sea_weights'");
}
