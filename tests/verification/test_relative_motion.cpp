// Relative bow motion, deck wetness and slamming (seas/relative_motion.h): the relative-motion transfer
// function against a hand combination of heave, pitch and the incident wave at one frequency; its moments in
// cases with a closed form; the Rayleigh exceedance against a simulated narrow-band Gaussian process; the
// probabilities and rates against their formulas evaluated here.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "seakeeping/motions/encounter_frequency.h"
#include "seas/relative_motion.h"

using namespace hullopt::sk;
using cd = std::complex<double>;

namespace {
constexpr double kG = 9.81;
constexpr double kU = 15.0;  // [m/s]

RaoTable ConstantTable(cd heave, cd pitch, double w0 = 0.1, double w1 = 6.0, int n = 120) {
  RaoTable t;
  t.speed_m_s = kU;
  t.g_m_s2 = kG;
  for (int i = 0; i < n; ++i) {
    const double w = w0 + (w1 - w0) * i / (n - 1);
    t.omega_rad_s.push_back(w);
    t.omega_e_rad_s.push_back(HeadSeaEncounterFrequency(w, kU, kG));
    t.heave.push_back(heave);
    t.pitch.push_back(pitch);
  }
  return t;
}

// Independent: trapezoid in ω_e of ω_eⁿ S_ζ(ω_e) over the spectrum's range used by the code.
double EncounterWaveMoment(const WaveSpectrum& s, int n, double w_lo, double w_hi) {
  constexpr int kPoints = 200000;
  const double e0 = HeadSeaEncounterFrequency(w_lo, kU, kG), e1 = HeadSeaEncounterFrequency(w_hi, kU, kG);
  const double h = (e1 - e0) / kPoints;
  double sum = 0.0;
  for (int i = 0; i <= kPoints; ++i) {
    const double we = e0 + i * h;
    const double w = HeadSeaWaveFrequency(we, kU, kG);
    const double f = std::pow(we, n) * s.Density(w) / HeadSeaEncounterJacobian(w, kU, kG);
    sum += (i == 0 || i == kPoints) ? 0.5 * f : f;
  }
  return sum * h;
}
}  // namespace

TEST_CASE("relative-motion RAO: a hand combination of heave, pitch and the wave at the station", "[relative]") {
  constexpr double kRoundOff = 1e-12;  // the same arithmetic in another order
  // Heave 0.8 m/m leading by 30 deg, pitch 1.1 rad/rad lagging by 50 deg, at ω = 0.9 rad/s, 12 m forward of
  // the CG. By hand: k = ω²/g; s = x3 − x·x5 with x5 = k·P; the wave at the station leads by k·x (a crest
  // reaches the bow first in head seas).
  const double w = 0.9, x = 12.0, k = w * w / kG;
  const double h_re = 0.8 * std::cos(30.0 * M_PI / 180), h_im = 0.8 * std::sin(30.0 * M_PI / 180);
  const double p_re = 1.1 * std::cos(-50.0 * M_PI / 180), p_im = 1.1 * std::sin(-50.0 * M_PI / 180);
  const double re = h_re - x * k * p_re - std::cos(k * x);
  const double im = h_im - x * k * p_im - std::sin(k * x);
  const cd r = RelativeMotionTransfer(cd(h_re, h_im), cd(p_re, p_im), w, x, kG);
  CHECK(r.real() == Approx(re).margin(kRoundOff));
  CHECK(r.imag() == Approx(im).margin(kRoundOff));
  // At the CG a ship that follows the wave exactly (heave 1, in phase, no pitch) has no relative motion.
  CHECK(std::abs(RelativeMotionTransfer(cd(1, 0), cd(0, 0), w, 0.0, kG)) < kRoundOff);
}

TEST_CASE("relative-motion moments: closed forms for a fixed ship and a heave in antiphase", "[relative]") {
  // Simpson (800 intervals) against a 2e5-point trapezoid of the same smooth integrand.
  constexpr double kQuadratureTolerance = 1e-4;
  const WaveSpectrum s(SeaState::JonswapTz(2.0, 6.0));
  const double lo = std::max(0.1, 0.2 * s.omega_peak()), hi = std::min(6.0, 12.0 * s.omega_peak());
  const double m0 = EncounterWaveMoment(s, 0, lo, hi), m2 = EncounterWaveMoment(s, 2, lo, hi);
  // A fixed ship: r = −ζ(x), |H_r| = 1 at every station: the moments of the encounter wave spectrum.
  const RaoTable fixed = ConstantTable(cd(0, 0), cd(0, 0));
  for (double x : {0.0, 20.0, -15.0}) {
    const RelativeMotionMoments r = RelativeMotionAt(fixed, s, x);
    CHECK(r.m0 == Approx(m0).epsilon(kQuadratureTolerance));
    CHECK(r.m2 == Approx(m2).epsilon(kQuadratureTolerance));
  }
  // Hs = 4√m0 of the whole spectrum; the table covers all but a negligible tail.
  constexpr double kTailTolerance = 1e-3;
  CHECK(RelativeMotionAt(fixed, s, 0.0).m0 == Approx(std::pow(2.0 / 4.0, 2)).epsilon(kTailTolerance));
  // Heave in antiphase at the CG: |H_r| = 2, four times the wave variance.
  const RelativeMotionMoments a = RelativeMotionAt(ConstantTable(cd(-1, 0), cd(0, 0)), s, 0.0);
  CHECK(a.m0 == Approx(4.0 * m0).epsilon(kQuadratureTolerance));
  // Following the wave at the CG: none.
  CHECK(RelativeMotionAt(ConstantTable(cd(1, 0), cd(0, 0)), s, 0.0).m0 < 1e-12);
}

TEST_CASE("Rayleigh exceedance of a simulated narrow-band Gaussian process", "[relative]") {
  // 100 components in ω 0.9..1.1 rad/s (a frequency drawn inside each bin, so the record does not repeat),
  // equal amplitudes, random phases: nearly Gaussian and narrow-band. Per zero up-crossing cycle, the share
  // of maxima above a equals exp(−a²/(2 m0)).
  constexpr int kComponents = 100;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> w(kComponents), ph(kComponents);
  const double amp = 0.1;
  for (int i = 0; i < kComponents; ++i) w[i] = 0.9 + 0.2 * (i + u(rng)) / kComponents, ph[i] = 2 * M_PI * u(rng);
  const double m0 = kComponents * amp * amp / 2.0;
  const double dt = 0.1, duration = 200000.0;
  long cycles = 0;
  std::vector<long> above(3, 0);
  const double levels[3] = {0.5 * std::sqrt(m0), 1.0 * std::sqrt(m0), 2.0 * std::sqrt(m0)};
  double prev = 0.0, peak = 0.0;
  bool started = false;
  for (double t = 0; t < duration; t += dt) {
    double v = 0.0;
    for (int i = 0; i < kComponents; ++i) v += amp * std::cos(w[i] * t + ph[i]);
    if (prev < 0.0 && v >= 0.0) {  // zero up-crossing closes a cycle
      if (started) {
        ++cycles;
        for (int k = 0; k < 3; ++k) above[k] += peak > levels[k];
      }
      started = true;
      peak = 0.0;
    }
    peak = std::max(peak, v);
    prev = v;
  }
  REQUIRE(cycles > 30000);
  // The envelope decorrelates over ~2π/Δω = 31 s, so 200000 s hold ~6000 independent amplitudes: sampling
  // error √(p(1−p)/n) ≤ 0.0065; the finite bandwidth and the 0.1 s step (peaks up to 0.1 % low) add less.
  // 0.02 absolute is three standard errors.
  constexpr double kStatisticalTolerance = 0.02;
  for (int k = 0; k < 3; ++k) {
    INFO("level " << levels[k] / std::sqrt(m0) << " sigma");
    CHECK(static_cast<double>(above[k]) / cycles == Approx(RayleighExceedance(levels[k], m0)).margin(kStatisticalTolerance));
  }
}

TEST_CASE("deck wetness and slamming probabilities, rates and Ochi's threshold against their formulas",
          "[relative]") {
  constexpr double kRoundOff = 1e-12;
  RelativeMotionMoments r;
  r.m0 = 0.36;  // rms relative motion 0.6 m
  r.m2 = 0.81;  // rms relative velocity 0.9 m/s
  // P_w = exp(−f²/(2 m0)) at f = 1.2 m: exp(−1.44/0.72) = exp(−2).
  CHECK(DeckWetnessProbability(1.2, r) == Approx(std::exp(-2.0)).epsilon(kRoundOff));
  // Ochi: exp(−T²/(2 m0) − v²/(2 m2)) at T = 0.6 m, v = 0.9 m/s: exp(−0.5 − 0.5) = exp(−1).
  CHECK(SlammingProbability(0.6, 0.9, r) == Approx(std::exp(-1.0)).epsilon(kRoundOff));
  // Mean zero up-crossing rate (1/2π)√(m2/m0) = 1.5/(2π) per s.
  CHECK(r.zero_crossings_per_s() == Approx(1.5 / (2 * M_PI)).epsilon(kRoundOff));
  CHECK(EventsPerHour(std::exp(-1.0), r) == Approx(3600.0 * 1.5 / (2 * M_PI) * std::exp(-1.0)).epsilon(kRoundOff));
  // 0.093 √(g L) for L = 100 m.
  CHECK(OchiThresholdVelocity(100.0, kG) == Approx(0.093 * std::sqrt(981.0)).epsilon(kRoundOff));
  // Degenerate and refused inputs.
  RelativeMotionMoments none;
  CHECK(DeckWetnessProbability(1.0, none) == 0.0);
  CHECK(EventsPerHour(0.5, none) == 0.0);
  CHECK_THROWS_AS(DeckWetnessProbability(0.0, r), std::invalid_argument);
  CHECK_THROWS_AS(SlammingProbability(-1.0, 1.0, r), std::invalid_argument);
  CHECK_THROWS_AS(RayleighExceedance(1.0, -1.0), std::invalid_argument);
}

TEST_CASE("relative motion of a single-frequency response crosses zero at the encounter frequency",
          "[relative]") {
  // A narrow JONSWAP (γ = 10) seen by a fixed ship: the mean zero-crossing rate of r is that of the encounter
  // wave, (1/2π)√(m2/m0) of S_ζ(ω_e), computed here independently.
  constexpr double kQuadratureTolerance = 1e-4;
  const WaveSpectrum s(SeaState::JonswapTp(1.0, 8.0, 10.0));
  const double lo = std::max(0.1, 0.2 * s.omega_peak()), hi = std::min(6.0, 12.0 * s.omega_peak());
  const double rate = std::sqrt(EncounterWaveMoment(s, 2, lo, hi) / EncounterWaveMoment(s, 0, lo, hi)) / (2 * M_PI);
  CHECK(RelativeMotionAt(ConstantTable(cd(0, 0), cd(0, 0)), s, 10.0).zero_crossings_per_s() ==
        Approx(rate).epsilon(kQuadratureTolerance));
}
