// The `calibrate:` config section: values and defaults reach the options; contradictory or incomplete
// sections are refused naming the key.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "calibration/calibrate_config.h"

using hullopt::calib::ReadCalibrateConfig;
using hullopt::io::YamlMap;
using namespace hullopt::opt;
using namespace hullopt::calib;

namespace {
// The data files a.csv and b.csv exist beside the config (their paths are checked when read, not their content).
const std::filesystem::path kDir = std::filesystem::path(HULLOPT_BINARY_DIR) / "calibrate_config_test";

YamlMap FromText(const std::string& text) {
  std::filesystem::create_directories(kDir);
  for (const char* f : {"a.csv", "b.csv"}) std::ofstream(kDir / f) << "\n";
  return YamlMap(YAML::Load(text), "", (kDir / "test.yaml").string(), YAML::Node(YAML::NodeType::Map));
}
}  // namespace

TEST_CASE("single-hull form with every option", "[calibrate-config]") {
  auto root = FromText(
      "speed: { Fn: 0.75 }\n"
      "calibrate:\n"
      "  data: [a.csv, b.csv]\n"
      "  mode: per_speed\n"
      "  weights: { heave: 2.0, pitch: 0.5 }\n"
      "  residual: relative\n"
      "  loss: { type: cauchy, scale: 0.2 }\n"
      "  use_phases: true\n"
      "  Cs_initial: 0.03\n"
      "  model: { synthetic_oscillator: { heave_natural_rad_s: 7.0 } }\n");
  const auto cfg = ReadCalibrateConfig(root);
  root.Finish();
  CHECK(cfg.speeds_Fn == std::vector<double>{0.75});
  CHECK(cfg.options.mode == CsFitMode::kPerCase);
  CHECK(cfg.options.heave_weight == 2.0);
  CHECK(cfg.options.pitch_weight == 0.5);
  CHECK(cfg.options.residual_scale == CsResidualScale::kRelative);
  CHECK(cfg.options.loss == CsRobustLoss::kCauchy);
  CHECK(cfg.options.loss_scale == 0.2);
  CHECK(cfg.options.use_phases);
  CHECK(cfg.options.Cs_initial == 0.03);
  REQUIRE(cfg.hulls.size() == 1);
  // Relative to the config's folder, absolute.
  CHECK(cfg.hulls[0].data_files == std::vector<std::string>{(kDir / "a.csv").string(), (kDir / "b.csv").string()});
  CHECK(root.resolved()["calibrate"]["data"][1].as<std::string>() == (kDir / "b.csv").string());
  REQUIRE(cfg.hulls[0].synthetic.has_value());
  CHECK(cfg.hulls[0].synthetic->heave_natural_rad_s == 7.0);
  CHECK(root.resolved()["calibrate"]["loss"]["type"].as<std::string>() == "cauchy");
}

TEST_CASE("several hulls, speeds_Fn and defaults", "[calibrate-config]") {
  auto root = FromText(
      "calibrate:\n"
      "  speeds_Fn: [0.5, 0.75]\n"
      "  mode: linear_in_parameter\n"
      "  parameter_name: B_over_T\n"
      "  hulls:\n"
      "    - { name: A, parameter: 1.5, data: [a.csv] }\n"
      "    - { name: B, parameter: 2.5, data: [b.csv] }\n");
  const auto cfg = ReadCalibrateConfig(root);
  root.Finish();
  CHECK(cfg.speeds_Fn.size() == 2);
  CHECK(cfg.parameter_name == "B_over_T");
  REQUIRE(cfg.hulls.size() == 2);
  CHECK(cfg.hulls[1].name == "B");
  CHECK(cfg.hulls[1].parameter == 2.5);
  CHECK_FALSE(cfg.hulls[0].synthetic.has_value());
  CHECK(cfg.options.heave_weight == 1.0);
  CHECK(cfg.options.loss == CsRobustLoss::kNone);
  CHECK(cfg.options.residual_scale == CsResidualScale::kAbsolute);
}

TEST_CASE("contradictory or incomplete calibrate sections are refused", "[calibrate-config][bad-input]") {
  auto fails = [](const std::string& text, const std::string& what) {
    auto root = FromText(text);
    CHECK_THROWS_WITH(ReadCalibrateConfig(root), Catch::Contains(what));
  };
  fails("speed: { Fn: 0.75 }\ncalibrate: { data: [a.csv], hulls: [{name: A, data: [a.csv]}] }\n",
        "either 'data'");
  fails("speed: { Fn: 0.75 }\ncalibrate: { mode: single }\n", "either 'data'");
  fails("speed: { Fn: 0.75 }\ncalibrate: { data: [a.csv, c.csv] }\n",
        "key 'calibrate.data': 'c.csv': no such file " + (kDir / "c.csv").string());
  fails("speed: { Fn: 0.75 }\ncalibrate: { data: [a.csv], mode: linear_in_parameter }\n",
        "at least two 'hulls'");
  fails("speed: { Fn: 0.75 }\ncalibrate: { speeds_Fn: [0.75], data: [a.csv] }\n", "not both");
  fails("speed: { m_s: 4.0 }\ncalibrate: { data: [a.csv] }\n", "give the speed as Fn");
  fails("speed: { Fn: 0.75 }\ncalibrate: { data: [a.csv], loss: { type: huber, scale: 0 } }\n",
        "key 'calibrate.loss.scale' = 0: must be > 0");
  fails("speed: { Fn: 0.75 }\ncalibrate: { data: [a.csv], Cs_initial: -0.1 }\n",
        "Cs is a damping coefficient");
  fails(
      "speed: { Fn: 0.75 }\ncalibrate: { data: [a.csv], model: { synthetic_oscillator: { heave_zeta0: 0 } } "
      "}\n",
      "heave_zeta0");
  fails("speed: { Fn: 0.75 }\ncalibrate: { data: [a.csv], model: { synthetic_oscillator: { zeta: 1 } } }\n",
        "unknown key 'calibrate.model.synthetic_oscillator.zeta'");
  fails("speed: { Fn: 0.75 }\ncalibrate:\n  hulls: [{name: A, data: [a.csv]}, {name: A, data: [b.csv]}]\n",
        "two hulls have this name");
}
