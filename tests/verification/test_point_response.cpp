// Point responses from complex RAOs: rms acceleration of synthetic RAOs against independent quadrature in
// encounter frequency, the sign and phase of s = x3 − x·x5, the quadratic-in-x shortcut against direct
// integration of the response spectrum, and the design evaluation (positions, mean, bad inputs).
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <string>

#include "seas/design_evaluation.h"
#include "seakeeping/motions/encounter_frequency.h"
#include "seas/point_response.h"

using namespace hullopt::sk;
using cd = std::complex<double>;

namespace {
constexpr double kG = 9.81;
constexpr double kU = 40.0 * 1852.0 / 3600.0;  // 40 kn [m/s]

template <class Heave, class Pitch>
RaoTable MakeTable(double w0, double w1, int n, Heave heave, Pitch pitch) {
  RaoTable t;
  t.speed_m_s = kU;
  t.g_m_s2 = kG;
  for (int i = 0; i < n; ++i) {
    const double w = w0 + (w1 - w0) * i / (n - 1);
    const double we = HeadSeaEncounterFrequency(w, kU, kG);
    t.omega_rad_s.push_back(w);
    t.omega_e_rad_s.push_back(we);
    t.heave.push_back(heave(w, we));
    t.pitch.push_back(pitch(w, we));
  }
  return t;
}

// Independent: trapezoid in ω_e of ω_eⁿ S_ζ(ω_e) on [ω_e(a), ω_e(b)], S_ζ(ω_e) = S(ω)/(1 + 2ωU/g).
double EncounterMoment(const WaveSpectrum& s, int n, double a, double b) {
  constexpr int kPoints = 200000;
  const double e0 = HeadSeaEncounterFrequency(a, kU, kG), e1 = HeadSeaEncounterFrequency(b, kU, kG);
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

TEST_CASE("constant heave RAO = 1: sigma_a^2 is the integral of omega_e^4 S over omega_e", "[response]") {
  constexpr double kQuadratureTolerance = 1e-4;  // Simpson (800) vs trapezoid (2e5) of a smooth integrand
  const auto t = MakeTable(
      0.2, 2.5, 40, [](double, double) { return cd(1.0, 0.0); }, [](double, double) { return cd(0.0, 0.0); });
  const WaveSpectrum s(SeaState::JonswapTz(1.0, 5.5));
  const SeaResponse r(t, s);
  REQUIRE(r.omega_min() == Approx(0.2));  // 0.2 ωp = 0.18 < table start
  REQUIRE(r.omega_max() == Approx(2.5));
  for (double x : {-20.0, 0.0, 15.0}) {  // no pitch: the same at every point
    const PointMoments m = r.Moments(x);
    CHECK(m.m4 == Approx(EncounterMoment(s, 4, 0.2, 2.5)).epsilon(kQuadratureTolerance));
    CHECK(m.m2 == Approx(EncounterMoment(s, 2, 0.2, 2.5)).epsilon(kQuadratureTolerance));
    CHECK(m.m0 == Approx(EncounterMoment(s, 0, 0.2, 2.5)).epsilon(kQuadratureTolerance));
  }
  // Truncation report: the wave energy above 2.5 rad/s is the ω⁻⁵ tail, fraction ≈ A_γ·1.25·(ωp/2.5)⁴ with
  // A_γ = 0.65734 (γ = 3.3); below 0.2 rad/s there is none. 3 % covers exp(−1.25(ωp/ω)⁴) ≈ 0.985 at 2.5
  // rad/s.
  constexpr double kTailTolerance = 0.03;
  CHECK(r.truncated_wave_energy_fraction() ==
        Approx(0.65734 * 1.25 * std::pow(s.omega_peak() / 2.5, 4)).epsilon(kTailTolerance));
}

TEST_CASE("pitch sign and phase: s = x3 - x x5 with x5 positive bow-down", "[response]") {
  // X5/A = c (pitch per kA = c/k), in phase with a unit heave: the point x = 1/c forward of the CG stays
  // still (bow-down pitch lowers it exactly as heave lifts it); x = −1/c aft moves twice the heave.
  constexpr double kC = 0.05;  // [rad/m]
  // 400 nodes: linear interpolation of 1/ω² between nodes is exact to ~1e-5 relative.
  constexpr double kCancelTolerance = 1e-6;  // residual m4 relative to the heave-only m4
  constexpr double kRelTolerance = 1e-4;
  const auto in_phase = MakeTable(
      0.2, 2.5, 400, [](double, double) { return cd(1.0, 0.0); },
      [](double w, double) { return cd(kC * kG / (w * w), 0.0); });
  const auto heave_only = MakeTable(
      0.2, 2.5, 400, [](double, double) { return cd(1.0, 0.0); },
      [](double, double) { return cd(0.0, 0.0); });
  const auto quadrature = MakeTable(
      0.2, 2.5, 400, [](double, double) { return cd(1.0, 0.0); },
      [](double w, double) { return cd(0.0, kC * kG / (w * w)); });
  const WaveSpectrum s(SeaState::JonswapTz(3.0, 7.5));
  const double m4_heave = SeaResponse(heave_only, s).Moments(0.0).m4;
  const SeaResponse r(in_phase, s);
  CHECK(r.Moments(1.0 / kC).m4 < kCancelTolerance * m4_heave);
  CHECK(r.Moments(-1.0 / kC).m4 == Approx(4.0 * m4_heave).epsilon(kRelTolerance));
  CHECK(r.Moments(0.0).m4 == Approx(m4_heave).epsilon(1e-12));
  // Pitch 90° out of phase with heave: |H|² = 1 + (x c)² on both sides of the CG.
  const SeaResponse q(quadrature, s);
  for (double x : {-30.0, -10.0, 10.0, 30.0})
    CHECK(q.Moments(x).m4 == Approx((1.0 + x * x * kC * kC) * m4_heave).epsilon(kRelTolerance));
}

TEST_CASE("quadratic-in-x moments agree with direct integration of the acceleration spectrum", "[response]") {
  // A resonant complex RAO (heave natural frequency 3 rad/s encounter, 20 % damping) with lagging pitch.
  constexpr double kSecondMethodTolerance = 2e-3;  // trapezoid on 20000 ω_e points vs Simpson in ω
  auto heave = [](double, double we) {
    const double r = we / 3.0;
    return 1.0 / cd(1.0 - r * r, 2.0 * 0.2 * r);
  };
  auto pitch = [&](double w, double we) { return 0.8 * heave(w, we) * std::polar(1.0, -0.5); };
  const auto t = MakeTable(0.15, 3.0, 120, heave, pitch);
  for (const SeaState& sea : {SeaState::JonswapTz(0.5, 5.0), SeaState::JonswapTz(3.0, 7.5)}) {
    const WaveSpectrum s(sea);
    const SeaResponse r(t, s);
    for (double x : {-25.0, 0.0, 12.0}) {
      const auto spec = PointResponseSpectrum(t, s, x, 20000);
      double m4 = 0.0, m0 = 0.0;
      for (size_t i = 1; i < spec.size(); ++i) {
        const double d = spec[i].omega_e - spec[i - 1].omega_e;
        m4 += 0.5 * (spec[i].acceleration + spec[i - 1].acceleration) * d;
        m0 += 0.5 * (spec[i].displacement + spec[i - 1].displacement) * d;
      }
      INFO("Hs " << sea.Hs_m << " x " << x);
      CHECK(r.Moments(x).m4 == Approx(m4).epsilon(kSecondMethodTolerance));
      CHECK(r.Moments(x).m0 == Approx(m0).epsilon(kSecondMethodTolerance));
    }
  }
}

TEST_CASE("design evaluation: standard positions, mean, user points", "[response][evaluation]") {
  const auto t = MakeTable(
      0.2, 2.5, 40, [](double, double) { return cd(1.0, 0.0); },
      [](double w, double) { return cd(0.0, 0.02 * kG / (w * w)); });
  const HullExtent hull{20.0, 30.0};
  const auto eval = EvaluateDesign(t, hull, {SeaState::JonswapTz(1.0, 5.5), SeaState::JonswapTz(3.0, 7.5)},
                                   {{"bridge", 25.0}});
  REQUIRE(eval.seas.size() == 2);
  const auto& sea = eval.seas[1];
  REQUIRE(sea.positions.size() == 4);
  CHECK(sea.positions[0].position == "forward");
  CHECK(sea.positions[0].x_from_cg_m == Approx(12.0));  // 0.6 × 20 m
  CHECK(sea.positions[1].position == "lcg");
  CHECK(sea.positions[1].x_from_cg_m == 0.0);
  CHECK(sea.positions[2].position == "transom");
  CHECK(sea.positions[2].x_from_cg_m == -20.0);
  CHECK(sea.positions[3].position == "bridge");
  // |H|² = 1 + (0.02 x)²: σ_a grows with |x|; the mean is over the three standard positions only.
  CHECK(sea.positions[2].rms_accel_g > sea.positions[0].rms_accel_g);
  CHECK(sea.positions[0].rms_accel_g > sea.positions[1].rms_accel_g);
  const double mean_msi =
      (sea.positions[0].msi_pct + sea.positions[1].msi_pct + sea.positions[2].msi_pct) / 3.0;
  CHECK(sea.mean.msi_pct == Approx(mean_msi));
  CHECK(sea.mean.position == "mean");
  CHECK(std::isnan(sea.mean.x_from_cg_m));
  // At the LCG: σ_a from the independent encounter-frequency quadrature; MSI from the Lloyd formula.
  const WaveSpectrum s(SeaState::JonswapTz(3.0, 7.5));
  const double m4 = EncounterMoment(s, 4, 0.2, 2.5), m2 = EncounterMoment(s, 2, 0.2, 2.5);
  CHECK(sea.positions[1].rms_accel_m_s2 == Approx(std::sqrt(m4)).epsilon(1e-4));
  CHECK(sea.positions[1].rms_accel_g == Approx(std::sqrt(m4) / kG).epsilon(1e-4));
  const double mean_abs_g = std::sqrt(2.0 / 3.14159265358979323846) * std::sqrt(m4) / kG;
  CHECK(sea.positions[1].msi_pct == Approx(MsiLloyd(mean_abs_g, std::sqrt(m4 / m2))).epsilon(1e-3));
  CHECK(sea.Tz_s == Approx(7.5));
  CHECK(sea.peak_omega_e_rad_s == Approx(1.54).epsilon(0.01));
  // Bigger sea, more sickness.
  CHECK(eval.seas[1].mean.msi_pct > eval.seas[0].mean.msi_pct);
}

TEST_CASE("design evaluation refuses bad inputs with clear messages", "[evaluation][bad-input]") {
  const auto t = MakeTable(
      0.2, 2.5, 40, [](double, double) { return cd(1.0, 0.0); }, [](double, double) { return cd(0.0, 0.0); });
  const HullExtent hull{20.0, 30.0};
  auto message = [&](auto&& call) {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(message([&] { EvaluateDesign(t, hull, std::vector<SeaState>{}); }).find("sea list is empty") !=
        std::string::npos);
  CHECK(message([&] {
          EvaluateDesign(t, hull, {SeaState::JonswapTz(-1.0, 7.5)});
        }).find("seas[0]: Hs_m = -1") != std::string::npos);
  CHECK(message([&] {
          EvaluateDesign(t, hull, {SeaState::JonswapTz(3.0, 7.5)}, {{"mast", 31.0}});
        }).find("'mast': x_from_cg_m = 31 is outside the hull") != std::string::npos);
  CHECK(message([&] {
          EvaluateDesign(t, hull, {SeaState::JonswapTz(3.0, 7.5)}, {{"aft", -20.5}});
        }).find("outside the hull") != std::string::npos);
  CHECK(message([&] {
          EvaluateDesign(t, hull, {SeaState::JonswapTz(3.0, 7.5)}, {{"mean", 1.0}});
        }).find("reserved") != std::string::npos);
  CHECK(message([&] {
          EvaluateDesign(t, HullExtent{0.0, 30.0}, {SeaState::JonswapTz(3.0, 7.5)});
        }).find("CG-to-transom 0 m") != std::string::npos);
  auto broken = t;
  broken.pitch.pop_back();
  CHECK(message([&] { EvaluateDesign(broken, hull, {SeaState::JonswapTz(3.0, 7.5)}); }).find("same length") !=
        std::string::npos);
  broken = t;
  broken.omega_e_rad_s[3] *= 1.1;
  CHECK(message([&] { EvaluateDesign(broken, hull, {SeaState::JonswapTz(3.0, 7.5)}); }).find("row 3") !=
        std::string::npos);
}
