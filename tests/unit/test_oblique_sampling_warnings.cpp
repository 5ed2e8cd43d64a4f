// sk::ObliqueSamplingWarnings (seakeeping/motions/rao_checks.h) on results built here from a single-degree-of-
// freedom resonance |X| = 1/|1 − (ω/ω0)² + 2iζ ω/ω0| (ω0 = 1 rad/s, ζ = 0.05, half-power band 2ζω0 = 0.1 rad/s):
//  - on a grid 0.2 rad/s apart the roll peak is under-sampled and flagged, naming the heading and the mode;
//  - on a grid 0.005 rad/s apart (20 samples in the half-power band) it is not;
//  - a heading where the mode is round-off (1e-15 of the peak, spiky) is not judged;
//  - heave and pitch are judged too, each in its own warning.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "seakeeping/motions/rao_checks.h"

using namespace hullopt;

namespace {
std::complex<double> Resonance(double w) {
  constexpr double kW0 = 1.0, kZeta = 0.05;
  return 1.0 / std::complex<double>(1.0 - (w / kW0) * (w / kW0), 2.0 * kZeta * w / kW0);
}

// Headings {180, 120}: roll resonates at 120 deg and is round-off at 180 deg; heave (dof 2) resonates at both
// when `heave` is set, else it is flat.
sk::ObliqueStripResult Result(double step, bool heave) {
  sk::ObliqueStripResult r;
  r.headings_deg = {180.0, 120.0};
  std::vector<double> omega;
  for (double w = 0.3; w <= 2.0 + 1e-12; w += step) omega.push_back(w);
  for (double h : r.headings_deg)
    for (std::size_t i = 0; i < omega.size(); ++i) {
      sk::ObliqueWaveResult wave;
      wave.heading_deg = h;
      wave.omega_rad_s = omega[i];
      wave.omega_e_rad_s = omega[i];
      wave.rao[2] = heave ? Resonance(omega[i]) : std::complex<double>(1.0, 0.0);
      wave.rao[3] = h == 120.0 ? Resonance(omega[i]) : std::complex<double>(1e-15 * ((i % 3) == 1), 0.0);
      wave.rao[4] = 0.5;
      r.waves.push_back(wave);
    }
  return r;
}
}  // namespace

TEST_CASE("an under-sampled oblique resonance is flagged per mode with its headings", "[unit][rao_checks]") {
  const std::vector<std::string> coarse = sk::ObliqueSamplingWarnings(Result(0.2, false));
  REQUIRE(coarse.size() == 1);
  INFO(coarse[0]);
  CHECK(coarse[0].rfind("roll RAO peak is under-sampled by the frequency grid at 1 of 2 headings (120 deg)", 0) == 0);
  CHECK(coarse[0].find("solver.frequencies") != std::string::npos);
  CHECK(coarse[0].find(',') == std::string::npos);  // it goes into CSV notes as it is

  CHECK(sk::ObliqueSamplingWarnings(Result(0.005, false)).empty());

  const std::vector<std::string> both = sk::ObliqueSamplingWarnings(Result(0.2, true));
  REQUIRE(both.size() == 2);
  CHECK(both[0].rfind("heave RAO peak is under-sampled by the frequency grid at 2 of 2 headings (180 120 deg)", 0) == 0);
  CHECK(both[1].rfind("roll RAO peak", 0) == 0);
}
