// Tank RAO CSV contract (docs/file-formats.md): the Delft 372 file reads as printed; bad files are refused
// with the file, line, column and rule.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "io/formats/input_error.h"
#include "io/formats/tank_rao_reader.h"

using hullopt::io::GroupTankRaoBySpeed;
using hullopt::io::InputError;
using hullopt::io::ReadTankRaoCsv;

namespace {
std::string Write(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::path(HULLOPT_BINARY_DIR) / "test_tank_rao_reader";
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}
const std::string kDelft = std::string(HULLOPT_SOURCE_DIR) + "/data/delft372/delft372_tank_rao_fn075.csv";
}  // namespace

TEST_CASE("Delft 372 Fn 0.75 file reads as printed in the file", "[tank-rao]") {
  const auto pts = ReadTankRaoCsv(kDelft);
  REQUIRE(pts.size() == 13);
  // First and last rows of data/delft372/delft372_tank_rao_fn075.csv (the extra wave_amp_mm column is
  // ignored).
  CHECK(pts[0].Fn == 0.75);
  CHECK(pts[0].has_lambda_over_L);
  CHECK_FALSE(pts[0].has_omega_e);
  CHECK(pts[0].lambda_over_L == 0.998);
  CHECK(pts[0].heave_amp == 0.194);
  CHECK(pts[0].pitch_amp == 0.172);
  CHECK(pts[0].has_heave_phase);
  CHECK(pts[0].heave_phase_deg == -145.897);
  CHECK(pts[0].pitch_phase_deg == 113.207);
  CHECK(pts[12].lambda_over_L == 2.012);
  CHECK(pts[12].pitch_phase_deg == -173.855);
  CHECK(pts[0].source == kDelft + ":2");
  const auto cases = GroupTankRaoBySpeed(pts, {0.75}, "", 0.0);
  REQUIRE(cases.size() == 1);
  CHECK(cases[0].points.size() == 13);
  CHECK(cases[0].label == "Fn 0.75");
}

TEST_CASE("omega_e, comments, blank lines, column order and empty phase cells", "[tank-rao]") {
  const auto f = Write("ok.csv",
                       "# measured at the CG\n"
                       "pitch_rao,heave_rao,omega_e_rad_s,Fn,pitch_phase_deg\n"
                       "\n"
                       "0.5,1.25,6.0,0.5,\n"
                       "0.6,1.5,7.0,0.75,12.5\n");
  const auto pts = ReadTankRaoCsv(f);
  REQUIRE(pts.size() == 2);
  CHECK(pts[0].has_omega_e);
  CHECK(pts[0].omega_e_rad_s == 6.0);
  CHECK(pts[0].heave_amp == 1.25);
  CHECK_FALSE(pts[0].has_pitch_phase);
  CHECK(pts[1].has_pitch_phase);
  CHECK(pts[1].source == f + ":5");
  const auto cases = GroupTankRaoBySpeed(pts, {0.75, 0.5}, "hullA", 2.0);
  REQUIRE(cases.size() == 2);
  CHECK(cases[0].points.size() == 1);
  CHECK(cases[0].points[0].Fn == 0.75);
  CHECK(cases[1].label == "hullA Fn 0.5");
  CHECK(cases[1].hull_parameter == 2.0);
}

TEST_CASE("bad tank files name file, line, column and rule", "[tank-rao][bad-input]") {
  const std::string h = "Fn,lambda_over_L,heave_rao,pitch_rao\n";
  auto fails = [](const std::string& file, const std::string& what) {
    CHECK_THROWS_WITH(ReadTankRaoCsv(file), Catch::Contains(what));
  };
  auto f = Write("missing_col.csv", "Fn,lambda_over_L,heave_rao\n0.75,1.0,0.5\n");
  fails(f, f + ":1: missing column 'pitch_rao'");
  f = Write("missing_freq.csv", "Fn,heave_rao,pitch_rao\n0.75,0.5,0.5\n");
  fails(f, "missing column 'omega_e_rad_s' or 'lambda_over_L'");
  f = Write("negative.csv", h + "0.75,1.0,0.5,0.4\n0.75,1.1,-0.2,0.4\n");
  fails(f, f + ":3: column 'heave_rao' = -0.2: an RAO magnitude must be >= 0");
  f = Write("text.csv", h + "0.75,1.0,0.5,abc\n");
  fails(f, f + ":2: column 'pitch_rao' = 'abc': not a number");
  f = Write("trailing.csv", h + "0.75,1.0,0.5x,0.4\n");
  fails(f, "column 'heave_rao' = '0.5x': not a number");
  f = Write("nan.csv", h + "0.75,1.0,nan,0.4\n");
  fails(f, "must be finite");
  f = Write("empty.csv", "");
  fails(f, f + ": empty file");
  f = Write("header_only.csv", h);
  fails(f, "no data rows");
  f = Write("fields.csv", h + "0.75,1.0,0.5\n");
  fails(f, f + ":2: 3 fields, the header has 4");
  f = Write("zero_fn.csv", h + "0,1.0,0.5,0.4\n");
  fails(f, "column 'Fn' = 0: must be > 0");
  f = Write("empty_cell.csv", h + "0.75,1.0,,0.4\n");
  fails(f, "column 'heave_rao' is empty");
  CHECK_THROWS_AS(ReadTankRaoCsv("/nonexistent/tank.csv"), InputError);
}

TEST_CASE("a speed in the data that the config does not define, and a config speed without data",
          "[tank-rao][bad-input]") {
  const auto f =
      Write("two_speeds.csv", "Fn,lambda_over_L,heave_rao,pitch_rao\n0.75,1.0,0.5,0.4\n0.6,1.0,0.5,0.4\n");
  const auto pts = ReadTankRaoCsv(f);
  CHECK_THROWS_WITH(GroupTankRaoBySpeed(pts, {0.75}, "", 0.0),
                    Catch::Contains(f + ":3: column 'Fn' = 0.6: not a speed of the config (Fn 0.75)"));
  CHECK_THROWS_WITH(GroupTankRaoBySpeed(pts, {0.75, 0.6, 0.9}, "", 0.0),
                    Catch::Contains("config speed Fn 0.9 has no rows"));
}
