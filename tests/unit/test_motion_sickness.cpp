// MSI formulas against hand-computed values of the published forms (docs/evaluate.md, 'Method'), the ISO
// 2631-1 W_f weighting against its parameters, and option checks.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "seas/iso2631_weighting.h"
#include "seas/motion_sickness.h"

using namespace hullopt::sk;

TEST_CASE("standard normal CDF", "[msi]") {
  CHECK(StandardNormalCdf(0.0) == Approx(0.5));
  CHECK(StandardNormalCdf(1.0) == Approx(0.8413447461).epsilon(1e-9));
  CHECK(StandardNormalCdf(-1.959963985) == Approx(0.025).epsilon(1e-8));
}

TEST_CASE("MSI of a = 0.1 g at 0.167 Hz: 32 % Lloyd form, 39 % 1974 form", "[msi]") {
  // Hand computation:
  //   Lloyd: ω = 2π·0.167 = 1.04929 rad/s, log10 ω = 0.020896, μ = −0.819 + 2.32·0.020896² = −0.817987,
  //          z = (log10 0.1 − μ)/0.4 = (−1 + 0.817987)/0.4 = −0.455032, Φ(z) = 0.324543 → 32.45 %.
  //   1974:  log10 0.167 = −0.777284, z = −2.128 + 9.277·0.777284 − 5.809·0.604170 − 1.851
  //          = −2.128 + 7.210864 − 3.509624 − 1.851 = −0.277760, Φ(z) = 0.390597 → 39.06 %.
  constexpr double kHandTolerance = 0.02;  // [%-points] hand arithmetic carried to 6 digits
  constexpr double kTwoPi = 6.28318530717958647692;
  CHECK(MsiLloyd(0.1, kTwoPi * 0.167) == Approx(32.454).margin(kHandTolerance));
  CHECK(MsiOHanlonMcCauley1974(0.1, 0.167) == Approx(39.060).margin(kHandTolerance));
  // Lloyd: at log10 ω = 0 the threshold is μ = −0.819, so a = 10^−0.819 g gives exactly 50 %.
  CHECK(MsiLloyd(std::pow(10.0, -0.819), 1.0) == Approx(50.0).margin(1e-9));
  // One σ (0.4 decade) above: Φ(1) = 84.13 %.
  CHECK(MsiLloyd(std::pow(10.0, -0.419), 1.0) == Approx(84.134).margin(1e-3));
  CHECK(MsiLloyd(0.0, 1.0) == 0.0);
}

TEST_CASE("McCauley 1976 time-dependent form", "[msi]") {
  // a = 0.2 g, f = 0.2 Hz, t = 120 min. log10 a = log10 f = −0.698970, (log10 f)² = 0.488559:
  //   z_a = −1.487408 + 6.484344 − 2.838038 − 1.851 = 0.307898
  //   z_t = 1.134·0.307898 + 1.989·2.079181 − 2.904 = 0.349156 + 4.135491 − 2.904 = 1.580647
  //   Φ(z_a) = 0.620920, Φ(z_t) = 0.943021 → 58.554 %.
  constexpr double kHandTolerance = 0.02;  // [%-points]
  CHECK(MsiMcCauley1976(0.2, 0.2, 120.0) == Approx(58.554).margin(kHandTolerance));
  // Long exposure: Φ(z_t) → 1 and the 1976 form tends to the 1974 one.
  CHECK(MsiMcCauley1976(0.2, 0.2, 1e7) == Approx(MsiOHanlonMcCauley1974(0.2, 0.2)).margin(1e-6));
}

TEST_CASE("MSI from moments uses mean |a| = sqrt(2/pi) sigma and sqrt(m4/m2)", "[msi]") {
  // Narrow-band motion at 1 rad/s: m2 = m0, m4 = m0 → σ_a = √m0, ω = 1 rad/s.
  constexpr double kG = 9.81;
  PointMoments m;
  m.m0 = m.m2 = m.m4 = m.m6 = std::pow(0.15 * kG, 2);
  const double mean_abs_g = std::sqrt(2.0 / 3.14159265358979323846) * 0.15;
  MsiOptions o;
  CHECK(MotionSicknessIncidence(m, o, kG) == Approx(MsiLloyd(mean_abs_g, 1.0)).epsilon(1e-12));
  o.statistic = AccelerationStatistic::kRms;
  CHECK(MotionSicknessIncidence(m, o, kG) == Approx(MsiLloyd(0.15, 1.0)).epsilon(1e-12));
  o.model = MsiModel::kOHanlonMcCauley1974;
  CHECK(MotionSicknessIncidence(m, o, kG) ==
        Approx(MsiOHanlonMcCauley1974(0.15, 1.0 / 6.28318530717958647692)).epsilon(1e-12));
  m.m6 = 4.0 * m.m4;  // acceleration zero-crossing frequency 2 rad/s
  CHECK(MsiCharacteristicFrequency(m, MsiFrequency::kAccelerationZeroCrossing) == Approx(2.0));
  CHECK(MsiCharacteristicFrequency(m, MsiFrequency::kDisplacementM4M2) == Approx(1.0));
  CHECK(MotionSicknessIncidence(PointMoments{}, MsiOptions{}, kG) == 0.0);
}

TEST_CASE("ISO 2631-1 W_f weighting and MSDV", "[msi]") {
  // Band-pass around 0.1–0.5 Hz: |W_f| ≈ 1 near 0.16–0.2 Hz, strongly attenuated at 0.01 Hz and 2 Hz.
  CHECK(Iso2631WfMagnitude(0.16) == Approx(1.0).margin(0.1));
  CHECK(Iso2631WfMagnitude(0.2) == Approx(1.0).margin(0.1));
  CHECK(Iso2631WfMagnitude(0.01) < 0.02);
  // Above f2 = 0.63 Hz the low pass (2nd order) and the f4 = 0.25 Hz transition (2nd order) both fall as f⁻²:
  // |W_f(2 Hz)| ≈ (0.63/2)² (0.25/2)² ≈ 1.55e-3 (high pass and upward step ≈ 1 there).
  CHECK(Iso2631WfMagnitude(2.0) == Approx(0.315 * 0.315 * 0.125 * 0.125).epsilon(0.15));
  // MSDV of a stationary process: a_w,rms √T. 0.5 m/s² for 2 h → 42.43 m/s^1.5; VI = K_m MSDV = 14.1 %.
  CHECK(IsoMotionSicknessDoseValue(0.5, 7200.0) == Approx(42.4264).epsilon(1e-5));
  PointMoments m;
  m.m4_iso_wf = 0.25;
  MsiOptions o;
  o.model = MsiModel::kIso2631Msdv;
  CHECK(MotionSicknessIncidence(m, o, 9.81) == Approx(42.4264 / 3.0).epsilon(1e-5));
  m.m4_iso_wf = 100.0;  // VI linear in MSDV: capped at 100 %
  CHECK(MotionSicknessIncidence(m, o, 9.81) == 100.0);
}

TEST_CASE("MSI options are checked", "[msi][bad-input]") {
  std::string e;
  MsiOptions o;
  CHECK(o.IsValid(&e));
  o.exposure_h = 4.0;
  CHECK_FALSE(o.IsValid(&e));
  CHECK(e.find("2-hour") != std::string::npos);
  o.model = MsiModel::kMcCauley1976;
  CHECK(o.IsValid(&e));
  o.exposure_h = 0.0;
  CHECK_FALSE(o.IsValid(&e));
  o.exposure_h = 2.0;
  o.iso_km = -1.0;
  CHECK_FALSE(o.IsValid(&e));
  CHECK_THROWS_AS(MotionSicknessIncidence(PointMoments{}, o, 9.81), std::invalid_argument);
}
