// Full-precision reference of the Delft 372 catamaran RAOs (Fn 0.75, 40 x 14 strips, both demihulls, Cs 0.024):
// the time-domain strip method with the transient Green-function kernel (45 wavelengths) and the conventional
// strip-theory comparator (10 wavelengths), against the values written by the code before the kernel and
// exponential-integral speed work (tests/data/kernel_reference/README.md: commit, command). Every value is
// printed with 17 significant digits, so the test reports whether the results are bitwise unchanged; it
// requires each RAO (as a complex value) within 1e-6 of its column's peak amplitude: far above the round-off
// of a changed summation order or table (~1e-12 relative) and far below any physical change (a 1% shift of
// the heave peak is 1e-2 of it). Set HULLOPT_RECORD_KERNEL_REFERENCE=1 to rewrite the files instead.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "seakeeping/motions/frequency_list.h"
#include "seakeeping/motions/rao_solver.h"
#include "support/delft372_hull.h"

namespace sk = hullopt::sk;

namespace {

constexpr double kG = 9.81, kRho = 1000.0, kL = 3.0;
constexpr double kPeakTolerance = 1e-6;  // of each column's peak amplitude (see the file comment)

sk::RaoTable Compute(sk::RaoSolverOptions::Method method, int wavelengths) {
  const double U = 0.75 * std::sqrt(kG * kL);
  const auto w = sk::WaveFrequencies(
      sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kLambdaOverL, 0.8, 3.0, wavelengths), U, kG, kL);
  return sk::ComputeRaos(hullopt::testing::Delft372Hull(HULLOPT_SOURCE_DIR), hullopt::testing::Delft372Mass(), U,
                         kRho, kG, w, hullopt::testing::Delft372SolverOptions(method),
                         sk::TransientGreenKernelBuilder());
}

// omega, Re/Im heave, Re/Im pitch per row.
using Rows = std::vector<std::vector<double>>;

Rows ToRows(const sk::RaoTable& t) {
  Rows r;
  for (std::size_t i = 0; i < t.omega_rad_s.size(); ++i)
    r.push_back({t.omega_rad_s[i], t.heave[i].real(), t.heave[i].imag(), t.pitch[i].real(), t.pitch[i].imag()});
  return r;
}

void Write(const std::string& path, const Rows& rows) {
  std::ofstream out(path);
  out << "omega_rad_s,heave_re,heave_im,pitch_re,pitch_im\n";
  char buf[64];
  for (const auto& row : rows) {
    for (std::size_t k = 0; k < row.size(); ++k) {
      std::snprintf(buf, sizeof buf, "%.17g", row[k]);
      out << (k ? "," : "") << buf;
    }
    out << "\n";
  }
}

Rows Read(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in.good());
  Rows rows;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) row.push_back(std::strtod(cell.c_str(), nullptr));
    rows.push_back(row);
  }
  return rows;
}

void Check(const std::string& name, const sk::RaoTable& table) {
  const std::string path = std::string(HULLOPT_SOURCE_DIR) + "/tests/data/kernel_reference/" + name + ".csv";
  const Rows now = ToRows(table);
  if (std::getenv("HULLOPT_RECORD_KERNEL_REFERENCE")) {
    Write(path, now);
    WARN("recorded " << path);
    return;
  }
  const Rows ref = Read(path);
  REQUIRE(ref.size() == now.size());
  int bitwise = 0;
  double worst[2] = {0.0, 0.0};
  for (int c = 0; c < 2; ++c) {  // heave, pitch
    double peak = 0.0;
    for (const auto& row : ref) peak = std::fmax(peak, std::hypot(row[1 + 2 * c], row[2 + 2 * c]));
    for (std::size_t i = 0; i < ref.size(); ++i) {
      REQUIRE(now[i][0] == ref[i][0]);  // the same frequencies
      const double d = std::hypot(now[i][1 + 2 * c] - ref[i][1 + 2 * c], now[i][2 + 2 * c] - ref[i][2 + 2 * c]);
      worst[c] = std::fmax(worst[c], d / peak);
      bitwise += now[i][1 + 2 * c] == ref[i][1 + 2 * c] && now[i][2 + 2 * c] == ref[i][2 + 2 * c];
      CHECK(d <= kPeakTolerance * peak);
    }
  }
  std::cout << name << ": " << bitwise << " of " << 2 * ref.size()
            << " complex RAOs bitwise equal to the reference; largest difference " << worst[0]
            << " (heave) and " << worst[1] << " (pitch) of the peak\n";
}

}  // namespace

TEST_CASE("Delft 372 40 x 14 transient-kernel RAOs against the recorded reference", "[verification][reference]") {
  Check("rao_delft372_40x14_td", Compute(sk::RaoSolverOptions::Method::kTimeDomainStrip, 45));
}

TEST_CASE("Delft 372 40 x 14 strip-theory RAOs against the recorded reference", "[verification][reference]") {
  Check("rao_delft372_40x14_stf", Compute(sk::RaoSolverOptions::Method::kStripTheory, 10));
}
