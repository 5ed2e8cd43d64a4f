// Frequency lists: λ/L, ω and ω_e lists and ranges to wave frequencies, encounter-frequency inversion,
// refusals.
#include <catch2/catch.hpp>
#include <cmath>

#include "seakeeping/motions/frequency_list.h"
#include "seakeeping/motions/head_sea_wave.h"

namespace sk = hullopt::sk;

TEST_CASE("encounter frequency and its inverse", "[frequency]") {
  const double U = 10.0, g = 9.81;
  // ω_e = ω + ω²U/g by hand: ω = 1 → 1 + 10/9.81.
  CHECK(sk::HeadSeaEncounterFrequency(1.0, U, g) == Approx(1.0 + 10.0 / 9.81).epsilon(1e-15));
  for (double w : {0.01, 0.5, 1.0, 3.0, 10.0})
    CHECK(sk::HeadSeaWaveFrequency(sk::HeadSeaEncounterFrequency(w, U, g), U, g) == Approx(w).epsilon(1e-13));
  CHECK(sk::HeadSeaWaveFrequency(2.0, 0.0, g) == 2.0);
  // λ = 2πg/ω²: λ = 2π·9.81 m ↔ ω = 1.
  CHECK(sk::WaveFrequencyFromLength(2 * M_PI * g, g) == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("frequency specs convert to increasing wave frequencies", "[frequency]") {
  const double U = 4.07, g = 9.81, L = 3.0;
  sk::FrequencySpec s;
  s.quantity = sk::FrequencySpec::Quantity::kLambdaOverL;
  s.values = {2.0, 1.0, 1.5};
  const auto w = sk::WaveFrequencies(s, U, g, L);
  REQUIRE(w.size() == 3);
  CHECK(w[0] == Approx(std::sqrt(2 * M_PI * g / (2.0 * L))));  // longest wave → lowest ω
  CHECK(w[2] == Approx(std::sqrt(2 * M_PI * g / (1.0 * L))));
  const auto r = sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kOmegaE, 2.0, 12.0, 6);
  REQUIRE(r.values.size() == 6);
  CHECK(r.values[1] == Approx(4.0));
  const auto we = sk::WaveFrequencies(r, U, g, L);
  CHECK(sk::HeadSeaEncounterFrequency(we.back(), U, g) == Approx(12.0));
}

TEST_CASE("empty or non-positive frequency lists are refused", "[frequency][errors]") {
  sk::FrequencySpec s;
  std::string err;
  CHECK_FALSE(s.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("empty"));
  s.values = {1.0, -0.5};
  CHECK_FALSE(s.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("-0.5") && Catch::Contains("> 0"));
  CHECK_THROWS_AS(sk::WaveFrequencies(s, 1.0, 9.81, 1.0), std::invalid_argument);
}
