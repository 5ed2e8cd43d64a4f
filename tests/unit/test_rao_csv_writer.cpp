// rao.csv: exact header, conventions in comments, amplitudes/phases/λ/L from complex RAOs, no NaN written.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <sstream>

#include "io/formats/rao_csv_writer.h"

TEST_CASE("rao.csv columns and values", "[rao_csv]") {
  hullopt::sk::RaoTable t;
  t.speed_m_s = 4.0;
  t.g_m_s2 = 9.81;
  t.omega_rad_s = {2.0};
  t.omega_e_rad_s = {2.0 + 4.0 * 4.0 / 9.81};
  t.heave = {std::complex<double>(0.0, 2.0)};   // |2|, +90°
  t.pitch = {std::complex<double>(-1.0, 0.0)};  // |1|, 180°
  const std::string s = hullopt::io::FormatRaoCsv(t, 3.0, {"hull: test"});
  std::istringstream in(s);
  std::string line, header, row;
  bool saw_note = false;
  while (std::getline(in, line)) {
    if (line.rfind("#", 0) == 0) {
      saw_note |= line == "# hull: test";
      continue;
    }
    if (header.empty()) {
      header = line;
    } else {
      row = line;
    }
  }
  CHECK(saw_note);
  CHECK(s.find("bow-down") != std::string::npos);
  CHECK(s.find("phase lead positive") != std::string::npos);
  CHECK(header ==
        "omega_e_rad_s,omega_rad_s,lambda_over_L,heave_amp,heave_phase_deg,pitch_amp,pitch_phase_deg");
  std::vector<double> v;
  std::istringstream r(row);
  for (std::string cell; std::getline(r, cell, ',');) v.push_back(std::stod(cell));
  REQUIRE(v.size() == 7);
  CHECK(v[2] == Approx(2 * M_PI * 9.81 / 4.0 / 3.0));  // λ/L = 2πg/ω²/L
  CHECK(v[3] == Approx(2.0));
  CHECK(v[4] == Approx(90.0));
  CHECK(v[5] == Approx(1.0));
  CHECK(std::fabs(v[6]) == Approx(180.0));
}

TEST_CASE("rao.csv refuses non-finite values", "[rao_csv][errors]") {
  hullopt::sk::RaoTable t;
  t.omega_rad_s = {1.5};
  t.omega_e_rad_s = {2.0};
  t.heave = {std::complex<double>(std::numeric_limits<double>::quiet_NaN(), 0.0)};
  t.pitch = {1.0};
  CHECK_THROWS_WITH(hullopt::io::FormatRaoCsv(t, 1.0, {}),
                    Catch::Contains("non-finite") && Catch::Contains("omega = 1.5"));
}
