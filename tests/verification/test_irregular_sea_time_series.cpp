// Time domain against spectral statistics: 30 simulated minutes of random-phase irregular head sea at 40 kn,
// accelerations at forward, LCG and transom from complex RAOs by superposition, give rms accelerations within
// 5 % of the spectral σ_a = √m4 and mean |a| within 5 % of √(2/π) σ_a (docs/evaluate.md, 'Method': |a| =
// √(2/π) σ_a). The RAOs here are synthetic; with the time-marching ship solver the same check applies to its
// a(t).
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>

#include "seakeeping/motions/encounter_frequency.h"
#include "seas/irregular_sea.h"
#include "seas/passenger_positions.h"
#include "seas/point_response.h"

using namespace hullopt::sk;
using cd = std::complex<double>;

namespace {
constexpr double kG = 9.81;
constexpr double kU = 40.0 * 1852.0 / 3600.0;

RaoTable CatamaranLikeTable() {  // heave peak 2 at ω_e 1.7 rad/s, pitch peak ~1.4 at 1.5 rad/s
  RaoTable t;
  t.speed_m_s = kU;
  t.g_m_s2 = kG;
  for (int i = 0; i < 80; ++i) {
    const double w = 0.2 + 2.3 * i / 79.0, we = HeadSeaEncounterFrequency(w, kU, kG);
    const double r3 = we / 1.7, r5 = we / 1.5;
    t.omega_rad_s.push_back(w);
    t.omega_e_rad_s.push_back(we);
    t.heave.push_back(1.0 / cd(1.0 - r3 * r3, 0.5 * r3));
    t.pitch.push_back(cd(0.0, -1.0) / cd(1.0 - r5 * r5, 0.74 * r5));
  }
  return t;
}
}  // namespace

TEST_CASE("30 simulated minutes reproduce the spectral rms and mean |a| at the three positions",
          "[time-domain]") {
  // Statistical sampling error of a 30-minute record (a few hundred response cycles): ~2–3 % on the rms.
  constexpr double kRmsTolerance = 0.05;      // acceptance criterion
  constexpr double kMeanAbsTolerance = 0.05;  // Gaussian mean |a| = 0.798 σ within the same record error
  constexpr double kDuration = 1800.0;        // [s]
  constexpr double kDt = 0.04;                // [s] 10 samples per period at the highest ω_e (15.6 rad/s)
  const RaoTable t = CatamaranLikeTable();
  for (const SeaState& sea : {SeaState::JonswapTz(3.0, 7.5), SeaState::JonswapTz(1.0, 5.5)}) {
    const WaveSpectrum s(sea);
    // Same band as the spectral integral: the RAO table's ω range ∩ [0.2 ωp, 12 ωp].
    IrregularSeaOptions o;
    o.components = 600;
    o.omega_min_rad_s = std::max(0.2, 0.2 * s.omega_peak());
    o.omega_max_rad_s = std::min(2.5, 12.0 * s.omega_peak());
    o.seed = 2003;
    const auto comps = IrregularSeaComponents(s, kU, kG, o);
    const SeaResponse spectral(t, s);
    for (const auto& p : StandardPassengerPositions(18.0)) {
      const auto a =
          PointAccelerationTimeSeries(t, comps, p.x_from_cg_m, kDt, static_cast<int>(kDuration / kDt));
      double sum2 = 0.0, sum_abs = 0.0;
      for (double v : a) sum2 += v * v, sum_abs += std::abs(v);
      const double rms = std::sqrt(sum2 / a.size()), mean_abs = sum_abs / a.size();
      const double sigma = spectral.Moments(p.x_from_cg_m).rms_acceleration_m_s2();
      INFO("Hs " << sea.Hs_m << " " << p.name << ": time-domain rms " << rms << " spectral " << sigma);
      CHECK(rms == Approx(sigma).epsilon(kRmsTolerance));
      CHECK(mean_abs == Approx(std::sqrt(2.0 / 3.14159265358979323846) * sigma).epsilon(kMeanAbsTolerance));
    }
  }
}

TEST_CASE("a realisation carries the spectrum's variance and is reproducible", "[time-domain]") {
  const WaveSpectrum s(SeaState::JonswapTz(2.0, 6.5));
  const auto c1 = IrregularSeaComponents(s, kU, kG);
  const auto c2 = IrregularSeaComponents(s, kU, kG);
  REQUIRE(c1.size() == 400);
  CHECK(c1[17].phase_rad == c2[17].phase_rad);
  double var = 0.0;
  for (const auto& c : c1) var += 0.5 * c.amplitude_m * c.amplitude_m;
  // Band 0.2–5 ωp holds all but the ω⁻⁵ tail above 5 ωp (≈ 0.657·1.25/625 = 0.13 %); bin sampling ~0.5 %.
  CHECK(4.0 * std::sqrt(var) == Approx(2.0).epsilon(0.01));
  CHECK(WaveElevationAtCg(c1, 0.0) == Approx(WaveElevationAtCg(c2, 0.0)));
  IrregularSeaOptions bad;
  bad.components = 3;
  CHECK_THROWS_AS(IrregularSeaComponents(s, kU, kG, bad), std::invalid_argument);
}
