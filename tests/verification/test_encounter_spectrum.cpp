// Head-sea encounter spectra: the modal encounter frequencies of the reference paper's Fig. 7 seas at 40 kn,
// energy conservation under ω → ω_e, and the inverse frequency map.
#include <catch2/catch.hpp>
#include <cmath>

#include "seakeeping/motions/encounter_frequency.h"
#include "seas/point_response.h"
#include "seas/wave_spectrum.h"

using namespace hullopt::sk;

namespace {
constexpr double kKnot = 1852.0 / 3600.0;  // [m/s]
constexpr double kG = 9.81;
}  // namespace

TEST_CASE("peak encounter frequencies of the paper's Fig. 7 seas at 40 kn", "[encounter]") {
  // Paper Fig. 7: 0.46 Hz (2.9 rad/s) in 0.5 m / 5 s and 0.25 Hz (1.6 rad/s) in 3 m / 7.5 s. Acceptance 5 %.
  constexpr double kPaperTolerance = 0.05;
  const double U = 40.0 * kKnot;
  const double we_small = PeakEncounterFrequency(WaveSpectrum(SeaState::JonswapTz(0.5, 5.0)), U, kG);
  const double we_large = PeakEncounterFrequency(WaveSpectrum(SeaState::JonswapTz(3.0, 7.5)), U, kG);
  CHECK(we_small == Approx(2.9).epsilon(kPaperTolerance));
  CHECK(we_large == Approx(1.6).epsilon(kPaperTolerance));
  // Theory-notes preface (Tz reading, γ = 3.3): about 2.98 and 1.54 rad/s, quoted to 3 digits.
  constexpr double kNotesTolerance = 0.01;
  CHECK(we_small == Approx(2.98).epsilon(kNotesTolerance));
  CHECK(we_large == Approx(1.54).epsilon(kNotesTolerance));
  // Closed form: d/dω [S(ω)/(1 + 2ωU/g)] = 0 is checked by finite differences around the found peak.
  const WaveSpectrum s(SeaState::JonswapTz(3.0, 7.5));
  const double w = HeadSeaWaveFrequency(we_large, U, kG);
  auto se = [&](double x) { return s.Density(x) / HeadSeaEncounterJacobian(x, U, kG); };
  CHECK(se(w) >= se(w * 1.001));
  CHECK(se(w) >= se(w * 0.999));
}

TEST_CASE("the encounter spectrum keeps the wave variance", "[encounter]") {
  constexpr double kVarianceTolerance = 2e-3;  // trapezoid on 20000 points, ω_e range holding ~all energy
  const double U = 40.0 * kKnot;
  const WaveSpectrum s(SeaState::JonswapTz(1.0, 5.5));
  const double we_max = HeadSeaEncounterFrequency(12.0 * s.omega_peak(), U, kG);
  const auto samples = HeadSeaEncounterSpectrum(s, U, kG, 1e-3, we_max, 20000);
  double m0 = 0.0;
  for (size_t i = 1; i < samples.size(); ++i)
    m0 += 0.5 * (samples[i].wave + samples[i - 1].wave) * (samples[i].omega_e - samples[i - 1].omega_e);
  CHECK(4.0 * std::sqrt(m0) == Approx(1.0).epsilon(kVarianceTolerance));
}

TEST_CASE("wave frequency from encounter frequency inverts the head-sea map", "[encounter]") {
  for (double U : {0.0, 5.0, 20.6}) {
    for (double w : {0.1, 0.5, 1.0, 2.0, 5.0}) {
      const double we = HeadSeaEncounterFrequency(w, U, kG);
      CHECK(HeadSeaWaveFrequency(we, U, kG) == Approx(w).epsilon(1e-12));
    }
  }
  CHECK(HeadSeaEncounterFrequency(1.0, 9.81, 9.81) == Approx(2.0));
}
