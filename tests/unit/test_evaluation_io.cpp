// rao.csv reading (round trip of complex RAOs and the speed), msi.csv (exact header, rows, mean row,
// quoting), summary.json keys and the paper-style figures.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/report/evaluation_report.h"
#include "io/formats/input_error.h"
#include "io/formats/rao_table_csv.h"
#include "io/report/seakeeping_plots.h"
#include "seas/design_evaluation.h"
#include "seakeeping/motions/encounter_frequency.h"

namespace io = hullopt::io;
namespace sk = hullopt::sk;

namespace {
constexpr double kG = 9.81;
constexpr double kU = 20.0;
constexpr double kPi = 3.14159265358979323846;

std::string TmpDir(const std::string& name) {
  const auto dir = std::filesystem::path(HULLOPT_BINARY_DIR) / "test_tmp" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::string ReadAll(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// Writes a rao.csv of heave 1.2∠30°·(1 + ω) and pitch 0.8∠−60°, as `hullopt rao` would.
std::string WriteRaoCsv(const std::string& dir, double speed) {
  const std::string path = dir + "/rao.csv";
  std::ofstream f(path);
  f << "# RAOs per unit wave amplitude; phases in degrees, lead positive\n";
  f << "omega_e_rad_s,omega_rad_s,lambda_over_L,heave_amp,heave_phase_deg,pitch_amp,pitch_phase_deg,extra\n";
  for (int i = 0; i < 30; ++i) {
    const double w = 0.2 + 0.1 * i;
    char line[256];
    std::snprintf(line, sizeof line, "%.6g,%.6g,%.6g,%.6g,30,0.8,-60,7\n",
                  sk::HeadSeaEncounterFrequency(w, speed, kG), w, 2 * kPi * kG / (w * w) / 50.0,
                  1.2 * (1 + w));
    f << line;
  }
  return path;
}

sk::RaoTable SyntheticTable() {
  sk::RaoTable t;
  t.speed_m_s = kU;
  t.g_m_s2 = kG;
  for (int i = 0; i < 50; ++i) {
    const double w = 0.2 + 0.06 * i, we = sk::HeadSeaEncounterFrequency(w, kU, kG);
    const std::complex<double> d(1.0 - std::pow(we / 1.7, 2), 0.5 * we / 1.7);
    t.omega_rad_s.push_back(w);
    t.omega_e_rad_s.push_back(we);
    t.heave.push_back(1.0 / d);
    t.pitch.push_back(std::complex<double>(0.0, -1.0) / d);
  }
  return t;
}

std::vector<io::EvaluatedDesign> TwoDesigns() {
  std::vector<io::EvaluatedDesign> designs(2);
  const std::vector<sk::SeaState> seas = {sk::SeaState::JonswapTz(1.0, 5.5),
                                          sk::SeaState::JonswapTz(3.0, 7.5)};
  for (int i = 0; i < 2; ++i) {
    auto& d = designs[i];
    d.name = i == 0 ? "hull, one" : "hull2";
    d.group = i == 0 ? "catamaran" : "swath";
    d.parameters = {{"Fr", 0.8 - 0.1 * i}, {"Cvp", 0.6 + 0.1 * i}};
    d.rao = SyntheticTable();
    d.hull = {20.0 + 5 * i, 25.0};
    d.evaluation = sk::EvaluateDesign(d.rao, d.hull, seas, {{"bridge", 10.0}});
  }
  return designs;
}
}  // namespace

TEST_CASE("rao.csv round trip: complex RAOs from amplitude and phase, speed from omega_e", "[io][rao]") {
  const std::string path = WriteRaoCsv(TmpDir("rao_csv"), kU);
  const sk::RaoTable t = io::ReadRaoTableCsv(path, kG);
  REQUIRE(t.omega_rad_s.size() == 30);
  CHECK(t.speed_m_s == Approx(kU).epsilon(1e-5));  // 6 significant digits in the file
  CHECK(t.omega_rad_s[3] == Approx(0.5));
  CHECK(std::abs(t.heave[3]) == Approx(1.8));
  CHECK(std::arg(t.heave[3]) == Approx(kPi / 6.0));
  CHECK(t.pitch[3].real() == Approx(0.4));  // 0.8 cos(−60°)
  CHECK(t.pitch[3].imag() == Approx(-0.8 * std::sqrt(3.0) / 2.0));
  CHECK(t.omega_e_rad_s[29] == Approx(3.1 + 3.1 * 3.1 * kU / kG).epsilon(1e-6));
}

TEST_CASE("bad rao.csv files are refused with file and line", "[io][rao][bad-input]") {
  const std::string dir = TmpDir("rao_csv_bad");
  auto error_of = [&](const std::string& text) {
    std::ofstream(dir + "/bad.csv") << text;
    try {
      io::ReadRaoTableCsv(dir + "/bad.csv", kG);
    } catch (const io::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string header =
      "omega_e_rad_s,omega_rad_s,heave_amp,heave_phase_deg,pitch_amp,pitch_phase_deg\n";
  CHECK(error_of("omega_rad_s,heave_amp\n1,2\n").find("lacks column 'omega_e_rad_s'") != std::string::npos);
  CHECK(error_of(header + "1,1,1,0,1,0\n").find("at least 2") != std::string::npos);
  CHECK(error_of(header + "1,1,1,0,1,0\n2,2,x,0,1,0\n").find("bad.csv:3: column 'heave_amp' = 'x'") !=
        std::string::npos);
  CHECK(error_of(header + "2,2,1,0,1,0\n1,1,1,0,1,0\n").find("must increase") != std::string::npos);
  CHECK(error_of(header + "1,1,1,0,1,0\n2.5,2,1,0,1,0\n3.5,3,1,0,1,0\n").find("one speed per file") !=
        std::string::npos);
  CHECK(error_of(header + "1,1,-1,0,1,0\n2,2,1,0,1,0\n").find(">= 0") != std::string::npos);
  CHECK_THROWS_AS(io::ReadRaoTableCsv(dir + "/missing.csv"), io::InputError);
}

TEST_CASE("msi.csv has the contract header, one row per position and a mean row", "[io][msi]") {
  const auto designs = TwoDesigns();
  const std::string dir = TmpDir("msi_csv");
  io::WriteMsiCsv(dir + "/msi.csv", designs);
  std::ifstream f(dir + "/msi.csv");
  std::string line;
  std::getline(f, line);
  CHECK(line == "design,Hs_m,Tz_s,position,x_from_cg_m,rms_accel_g,msi_pct,notes");
  std::vector<std::string> rows;
  while (std::getline(f, line)) rows.push_back(line);
  REQUIRE(rows.size() == 2 * 2 * 5);  // designs × seas × (forward, lcg, transom, bridge, mean)
  CHECK(rows[0].rfind("\"hull, one\",1,5.5,forward,12,", 0) == 0);
  CHECK(rows[1].rfind("\"hull, one\",1,5.5,lcg,0,", 0) == 0);
  CHECK(rows[2].rfind("\"hull, one\",1,5.5,transom,-20,", 0) == 0);
  CHECK(rows[3].rfind("\"hull, one\",1,5.5,bridge,10,", 0) == 0);
  CHECK(rows[4].rfind("\"hull, one\",1,5.5,mean,,", 0) == 0);
  CHECK(rows[10].rfind("hull2,1,5.5,forward,15,", 0) == 0);
  // The mean row's MSI is the mean of the three standard rows (read back from the text).
  auto msi = [](std::string row) {  // the field before the (empty) notes
    row = row.substr(0, row.rfind(','));
    return std::stod(row.substr(row.rfind(',') + 1));
  };
  CHECK(msi(rows[9]) == Approx((msi(rows[5]) + msi(rows[6]) + msi(rows[7])) / 3.0).epsilon(1e-5));
}

TEST_CASE("evaluation outputs: summary.json and the paper-style plots", "[io][plots]") {
  const auto designs = TwoDesigns();
  const std::string dir = TmpDir("outputs");
  const auto files = io::WriteEvaluationOutputs(dir, designs, sk::EvaluationOptions{});
  for (const char* name : {"msi.csv", "summary.json", "encounter_spectra.svg", "raos.svg", "accel_per_m.svg",
                           "accel_per_m_vs_Hs.svg", "msi_vs_Hs.svg", "msi_vs_Fr.svg", "msi_vs_Cvp.svg"}) {
    INFO(name);
    CHECK(std::find(files.begin(), files.end(), name) != files.end());
    CHECK(std::filesystem::file_size(dir + "/" + name) > 100);
  }
  CHECK(std::find(files.begin(), files.end(), "msi_vs_B_over_T.svg") == files.end());  // no design has it
  const std::string json = ReadAll(dir + "/summary.json");
  for (const char* key :
       {"\"designs\"", "\"msi\"", "\"model\": \"lloyd\"", "\"rms_accel_g_per_m\"", "\"peak_omega_e_rad_s\"",
        "\"mean_msi_pct\"", "\"truncated_wave_energy_fraction\""}) {
    INFO(key);
    CHECK(json.find(key) != std::string::npos);
  }
  const std::string fig11 = io::RenderSvg(io::MsiVsHsFigure(designs));
  CHECK(fig11.find("MSI — catamaran") != std::string::npos);
  CHECK(fig11.find("MSI — swath") != std::string::npos);
  CHECK(fig11.find("1 hull, one") != std::string::npos);
  const std::string fig10 = io::RenderSvg(io::AccelerationPerMetreFigure(designs, 1));
  CHECK(fig10.find("Hs 3 m, Tz 7.5 s") != std::string::npos);
  CHECK(fig10.find("σ_a / Hs [g/m]") != std::string::npos);
  CHECK(io::ReferenceSeaIndex(designs[0].evaluation.seas) == 1);
  CHECK_THROWS_AS(io::WriteEvaluationOutputs(dir, {}, sk::EvaluationOptions{}), io::InputError);
}

TEST_CASE("plots keep a design's own number (12_TRIa stays 12 when hull 11 is left out)", "[io][plots]") {
  auto designs = TwoDesigns();
  designs[0].name = "10_SW2";
  designs[1].name = "12_TRIa";
  designs[1].group = designs[0].group;  // one panel, so the x positions are comparable
  for (auto& d : designs) d.parameters["Fr"] = 0.7;
  const std::string fr = io::RenderSvg(io::MsiVsParameterFigure(designs, "Fr", "Fr [-]", 1));
  CHECK(fr.find(">12<") != std::string::npos);
  CHECK(fr.find(">10<") != std::string::npos);
  const auto fig = io::AccelerationPerMetreFigure(designs, 1);
  REQUIRE(fig.panels.size() == 1);
  CHECK(fig.panels[0].x_ticks == std::vector<double>{10.0, 12.0});
  CHECK(fig.panels[0].series[0].x == std::vector<double>{10.0, 12.0});
}
