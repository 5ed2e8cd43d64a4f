// Bad hull input of every kind is refused with one line naming the file/line or key and the rule; good input
// parses into the option structs. Runs the same path as `hullopt hull` (config parsers, readers, generator).
#include <catch2/catch.hpp>
#include <fstream>
#include <string>

#include "io/config/hull_config.h"
#include "io/config/speed_config.h"
#include "io/config/water_config.h"

using namespace hullopt;

namespace {
const std::string kDir = HULLOPT_BINARY_DIR "/hull_inputs_test";

std::string Write(const std::string& name, const std::string& text) {
  std::system(("mkdir -p " + kDir).c_str());
  const std::string path = kDir + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// Runs the hull pipeline on a config text; returns the error message ("" if none).
std::string Run(const std::string& config_text) {
  const std::string cfg = Write("config.yaml", config_text);
  try {
    io::YamlMap root = io::YamlMap::LoadFile(cfg);
    const io::WaterOptions water = io::ParseWater(root);
    const io::HullOptions hull = io::ParseHullConfig(root, water);
    io::ParseSpeed(root, false);
    root.Finish();
    io::LoadHull(hull, cfg);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kParam =
    "hull:\n  parametric: {type: catamaran, displacement_t: 1000, L_over_B: 11, B_over_T: 2, Cb: 0.4, Cp: "
    "0.69, "
    "Cwp: 0.76, LCB_pct_L: -6.4, LCF_pct_L: -8.3";

std::string Param(const std::string& extra) { return kParam + extra + "}\n"; }

std::string Offsets(const std::string& csv_name) {
  return "hull:\n  offsets_csv: " + kDir + "/" + csv_name + "\n  draught_m: 0.15\n";
}

const std::string kGoodCsv = "x_m,y_m,z_m\n0,0,0\n0,0.1,0.3\n1,0,0\n1,0.1,0.3\n2,0,0.1\n2,0.05,0.3\n";

void CheckOneLine(const std::string& msg, const std::string& a, const std::string& b) {
  INFO(msg);
  CHECK(!msg.empty());
  CHECK(msg.find('\n') == std::string::npos);
  CHECK_THAT(msg, Catch::Contains(a) && Catch::Contains(b));
}
}  // namespace

TEST_CASE("good parametric and offsets configs load", "[hull-config]") {
  CHECK(Run(Param("") + "speed: {kn: 40}\nwater: {rho_kg_m3: 1025}\n") == "");
  Write("good.csv", kGoodCsv);
  CHECK(Run(Offsets("good.csv")) == "");
  CHECK(Run(Offsets("good.csv") + "  stations: 11\n") == "");
}

TEST_CASE("bad hull inputs: one line naming key or line and the rule", "[hull-config][bad-input]") {
  // 1 missing key
  CheckOneLine(Run("hull:\n  parametric: {type: catamaran, displacement_t: 1000}\n"), "missing required key",
               "hull.parametric.L_over_B");
  // 2 wrong type
  CheckOneLine(Run(Param(", keel_rise: high")), "hull.parametric.keel_rise", "must be a number");
  // 3 unknown key
  CheckOneLine(Run(Param(", Cbb: 0.4")), "unknown key 'hull.parametric.Cbb'", "misspelt");
  // 4 negative value
  CheckOneLine(Run("hull:\n  parametric: {type: monohull, displacement_t: -5, L_over_B: 8, B_over_T: 4, Cb: "
                   "0.4, Cp: 0.6, Cwp: 0.8, LCB_pct_L: 0, LCF_pct_L: 0}\n"),
               "displacement_t", "must be > 0");
  // 5 NaN
  CheckOneLine(Run(Param(", transom_immersion: .nan")), "transom_immersion", "NaN");
  // 6 Cp >= 1
  CheckOneLine(Run("hull:\n  parametric: {type: monohull, displacement_t: 100, L_over_B: 8, B_over_T: 4, Cb: "
                   "0.4, Cp: 1.0, Cwp: 0.8, LCB_pct_L: 0, LCF_pct_L: 0}\n"),
               "key 'hull.parametric.Cp' = 1.0", "must lie in (0, 1)");
  // 7 Cm > 1
  CheckOneLine(Run("hull:\n  parametric: {type: monohull, displacement_t: 100, L_over_B: 8, B_over_T: 4, Cb: "
                   "0.7, Cp: 0.6, Cwp: 0.8, LCB_pct_L: 0, LCF_pct_L: 0}\n"),
               "Cm = Cb/Cp", "must be <= 1");
  // 8 impossible SWATH
  CheckOneLine(Run("hull:\n  parametric: {type: swath, displacement_t: 1000, L_over_B: 14, B_over_T: 2, Cb: "
                   "0.5, Cp: 0.75, Cwp: 0.6, LCB_pct_L: -5, LCF_pct_L: -5, strut_ratio: 0.95}\n"),
               "impossible SWATH", "Cm = Cb/Cp");
  // 9 unknown speed unit / two units
  CheckOneLine(Run(Param("") + "speed: {kn: 40, Fn: 0.8}\n"), "key 'speed'", "exactly one of Fn, kn, m_s");
  // 10 both sources
  CheckOneLine(Run(Param("") + "  offsets_csv: x.csv\n"), "key 'hull'",
               "exactly one of parametric, offsets_csv, stl");
  // 11 non-existent file
  CheckOneLine(Run(Offsets("missing.csv")), "hull.offsets_csv' = " + kDir + "/missing.csv", "no such file");
  // 12 malformed CSV row
  Write("malformed.csv", "x_m,y_m,z_m\n0,0,0\n0,0.1\n");
  CheckOneLine(Run(Offsets("malformed.csv")), "malformed.csv:3", "malformed row");
  // 13 non-numeric CSV value
  Write("text.csv", "x_m,y_m,z_m\n0,0,0\n0,abc,0.3\n");
  CheckOneLine(Run(Offsets("text.csv")), "text.csv:3", "y_m = 'abc' is not a number");
  // 14 station with no waterline crossing
  Write("low.csv", "x_m,y_m,z_m\n0,0,0\n0,0.1,0.3\n1,0,0\n1,0.1,0.1\n");
  CheckOneLine(Run(Offsets("low.csv")), "low.csv:4", "no waterline crossing");
  // 15 bad header
  Write("header.csv", "x,y,z\n0,0,0\n");
  CheckOneLine(Run(Offsets("header.csv")), "header.csv:1", "header must start with x_m,y_m,z_m");
  // 16 station off the centreline, and z going down
  Write("offcl.csv", "x_m,y_m,z_m\n0,0.05,0\n0,0.1,0.3\n");
  CheckOneLine(Run(Offsets("offcl.csv")), "offcl.csv:2", "starts at the keel on the centreline");
  Write("down.csv", "x_m,y_m,z_m\n0,0,0.2\n0,0.1,0.1\n");
  CheckOneLine(Run(Offsets("down.csv")), "down.csv:3", "z must not decrease");
  // 17 empty and truncated STL
  Write("empty.stl", "");
  CheckOneLine(Run("hull:\n  stl: " + kDir + "/empty.stl\n  draught_m: 0.1\n"), "empty.stl", "empty");
  std::string bin(84, '\0');
  bin[80] = 10;  // announces 10 triangles, has none
  Write("trunc.stl", bin);
  CheckOneLine(Run("hull:\n  stl: " + kDir + "/trunc.stl\n  draught_m: 0.1\n"), "trunc.stl",
               "truncated or corrupt binary STL");
  Write("trunc_ascii.stl", "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n");
  CheckOneLine(Run("hull:\n  stl: " + kDir + "/trunc_ascii.stl\n  draught_m: 0.1\n"), "trunc_ascii.stl",
               "truncated ASCII STL");
  // 18 two hulls without spacing
  Write("good.csv", kGoodCsv);
  CheckOneLine(Run(Offsets("good.csv") + "  hulls: 2\n"), "hull.spacing_m", "must be > 0");
  // 19 water density out of range
  CheckOneLine(Run(Param("") + "water: {rho_kg_m3: 10}\n"), "water.rho_kg_m3", "must lie in [500, 2000]");
  // 20 Cwp / LCF beyond what any waterplane can do
  CheckOneLine(Run(kParam.substr(0, kParam.find("Cwp")) + "Cwp: 0.95, LCB_pct_L: -6.4, LCF_pct_L: -9}\n"),
               "LCF_pct_L = -9", "rule");
}
