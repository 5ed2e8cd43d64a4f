// The time-marching schemes on a closed-form problem: the damped linear oscillator
//   (M + A) a + b v + c x = F cos ωt,
// marched with the ship's split: the scheme asks for the "hull" acceleration F_h/M at a trial state, with
//   F_h = F cos ωt − b v − c x − A â,  â = 2 (v − v_K)/Δt − a_K  (the trial acceleration the state implies),
// so that A plays the kernel's instantaneous added mass. The references are derived here by algebra, not by
// running the schemes:
// - exact steady state X = F / (c − m ω² + i b ω), m = M + A;
// - implicit trapezoid (Newmark average acceleration): at the time steps, the exact steady state at the warped
//   frequency Ω = (2/Δt) tan(ωΔt/2) ≈ ω (1 + (ωΔt)²/12);
// - one weighted-average pass: the steady state of its recursion with the extrapolation factor E = 2/z − 1/z²
//   (z = e^{iωΔt}) in place of 1.
// The stability bounds come from the force's response to the trial acceleration, dF_h/dâ = −A_eff with
// A_eff = A + b Δt/2 + c Δt²/4 (added mass, and the damping and stiffness acting through the trial v and x):
// ρ = 1 − w (1 + A_eff/M); the repeated passes converge for |ρ| < 1, the single pass is stable for −1/3 < ρ < 1.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <vector>

#include "seakeeping/motions/time_scheme_registry.h"

namespace sk = hullopt::sk;
using cd = std::complex<double>;

namespace {

struct Oscillator {
  double M = 1.0;            // "ship" mass [kg]
  double A = 1.5;            // instantaneous added mass [kg]
  double c = 2.5;            // stiffness [N/m]: ω_n = sqrt(c/(M + A)) = 1 rad/s
  double b = 0.5;            // damping [N s/m]: ζ = b/(2 m ω_n) = 0.1
  double F = 1.0;            // forcing amplitude [N]
  double omega = 0.8;        // forcing frequency [rad/s]
  double dt = 0.13 / 0.8;    // ω Δt = 0.13
  double m() const { return M + A; }
  double A_eff() const { return A + b * dt / 2 + c * dt * dt / 4; }
  double rho(double w) const { return 1.0 - w * (1.0 + A_eff() / M); }
  cd Response(double frequency) const { return F / (c - m() * frequency * frequency + cd(0, 1) * b * frequency); }
  double Warped() const { return 2.0 / dt * std::tan(omega * dt / 2); }
  // Steady state of the single weighted-average pass (extrapolated â = E a).
  cd SinglePass(double w) const {
    const cd z = std::exp(cd(0, omega * dt));
    const cd E = 2.0 / z - 1.0 / (z * z);
    const cd v_per_a = dt / 2 * (1.0 + E * z) / (z - 1.0);
    const cd x_per_a = (dt * v_per_a + dt * dt / 4 * (1.0 + E * z)) / (z - 1.0);
    const cd alpha = (w * F / M) / (1.0 - (1.0 - w) * E + w * A * E / M + w / M * (b * v_per_a + c * x_per_a));
    return alpha * x_per_a;
  }
};

struct Run {
  std::vector<double> t, x, a;
  bool finite = true;
};

Run March(const Oscillator& o, sk::TimeSchemeKind kind, double w, int steps, int max_passes = 200) {
  sk::WeightedAverageParameters p;
  p.hydrodynamic_fraction = w;
  p.max_passes = max_passes;
  auto scheme = sk::MakeTimeScheme(kind, p);
  scheme->Restart();
  sk::MarchingState s;
  Run r;
  double t = 0.0;
  for (int k = 0; k < steps; ++k) {
    const sk::MarchingState before = s;
    t += o.dt;
    scheme->Step(
        o.dt,
        [&](const sk::DofPair& x, const sk::DofPair& v, int) -> sk::DofPair {
          const double a_trial = 2.0 * (v[0] - before.v[0]) / o.dt - before.a[0];
          const double f = o.F * std::cos(o.omega * t) - o.b * v[0] - o.c * x[0] - o.A * a_trial;
          return {f / o.M, 0.0};
        },
        &s);
    r.t.push_back(t);
    r.x.push_back(s.x[0]);
    r.a.push_back(s.a[0]);
    if (!std::isfinite(s.x[0]) || !std::isfinite(s.a[0])) {
      r.finite = false;
      break;
    }
  }
  return r;
}

// Least-squares x ≈ c0 + c cos ωt + s sin ωt over the last `count` samples; X = c − i s.
cd Fit(const Run& r, double omega, std::size_t count) {
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  for (std::size_t i = r.t.size() - count; i < r.t.size(); ++i) {
    const Eigen::Vector3d row(1.0, std::cos(omega * r.t[i]), std::sin(omega * r.t[i]));
    ata += row * row.transpose();
    atb += row * r.x[i];
  }
  const Eigen::Vector3d k = ata.ldlt().solve(atb);
  return {k[1], -k[2]};
}

double MaxAbs(const std::vector<double>& v, std::size_t last) {
  double m = 0.0;
  for (std::size_t i = v.size() - last; i < v.size(); ++i) m = std::max(m, std::fabs(v[i]));
  return m;
}

// 4000 steps = 650 s: transients decay as e^{−ζ ω_n t} = e^{−65}, below rounding. Fit over the last 1000
// steps (about 20 periods).
constexpr int kSteps = 4000;
constexpr std::size_t kFitSamples = 1000;
// A scheme against its own discrete steady state (algebra above): the passes stop when â changes by less
// than 1e-7 of max|a|, which leaves a fixed-point error of ρ/(1 − ρ) · 1e-7 ≈ 3e-7 per step at w = 0.2,
// amplified up to 1/(2ζ) = 5 near resonance; 1e-5 is that bound with margin. The single pass has no pass
// tolerance; its residual is rounding and the fit (4e-13 measured).
constexpr double kPassesTol = 1e-5;
constexpr double kSinglePassTol = 1e-8;

}  // namespace

TEST_CASE("time schemes are chosen by name", "[time_scheme]") {
  const auto names = sk::TimeSchemeNames();
  REQUIRE(names.size() == 2);
  CHECK(names[0] == "weighted_average_trapezoid");
  sk::TimeSchemeKind kind = sk::TimeSchemeKind::kWeightedAverageTrapezoid;
  REQUIRE(sk::FindTimeScheme("paper_single_pass", &kind));
  CHECK(kind == sk::TimeSchemeKind::kPaperSinglePass);
  CHECK(sk::TimeSchemeName(kind) == "paper_single_pass");
  CHECK_FALSE(sk::FindTimeScheme("rk4", &kind));
  sk::WeightedAverageParameters bad;
  bad.hydrodynamic_fraction = 0.0;
  CHECK_THROWS_WITH(sk::MakeTimeScheme(sk::TimeSchemeKind::kPaperSinglePass, bad),
                    Catch::Contains("hydrodynamic_fraction"));
}

TEST_CASE("weighted_average_trapezoid: the implicit trapezoid steady state, warped by (omega dt)^2/12", "[time_scheme]") {
  const Oscillator o;
  const cd exact = o.Response(o.omega);
  const cd trapezoid = o.Response(o.Warped());
  // The warp itself: Ω/ω − 1 = (ωΔt)²/12 + (ωΔt)⁴/120 + ...
  const double theta = o.omega * o.dt;
  CHECK(o.Warped() / o.omega - 1.0 == Approx(theta * theta / 12).epsilon(theta * theta / 10 * 1.01));
  for (double w : {0.2, 0.4}) {
    const Run r = March(o, sk::TimeSchemeKind::kWeightedAverageTrapezoid, w, kSteps);
    REQUIRE(r.finite);
    const cd X = Fit(r, o.omega, kFitSamples);
    const double vs_trapezoid = std::abs(X - trapezoid) / std::abs(trapezoid);
    const double vs_exact = std::abs(X - exact) / std::abs(exact);
    const double warp = std::abs(trapezoid - exact) / std::abs(exact);
    INFO("w = " << w << ": |X − X_trapezoid|/|X_trapezoid| = " << vs_trapezoid << ", |X − X_exact|/|X_exact| = "
                << vs_exact << " (warp alone " << warp << ")");
    CHECK(vs_trapezoid < kPassesTol);
    // Against the exact steady state the error is the warp's (independent of w), not the extrapolation's.
    CHECK(std::fabs(vs_exact - warp) < kPassesTol);
    WARN("weighted_average_trapezoid w = " << w << ": error vs exact " << vs_exact << ", vs trapezoid closed form "
                                           << vs_trapezoid << ", warp prediction " << warp);
  }
}

TEST_CASE("paper_single_pass: its recursion's steady state, off the exact one by the amplified extrapolation",
          "[time_scheme]") {
  const Oscillator o;
  const cd exact = o.Response(o.omega);
  const cd trapezoid = o.Response(o.Warped());
  const double warp = std::abs(trapezoid - exact) / std::abs(exact);
  std::vector<double> errors;
  for (double w : {0.2, 0.4}) {
    const Run r = March(o, sk::TimeSchemeKind::kPaperSinglePass, w, kSteps);
    REQUIRE(r.finite);
    const cd X = Fit(r, o.omega, kFitSamples);
    const cd single = o.SinglePass(w);
    const double vs_closed_form = std::abs(X - single) / std::abs(single);
    const double vs_exact = std::abs(X - exact) / std::abs(exact);
    INFO("w = " << w << ": vs own closed form " << vs_closed_form << ", vs exact " << vs_exact);
    CHECK(vs_closed_form < kSinglePassTol);
    // The extrapolation error comes on top of the trapezoid's warp.
    CHECK(vs_exact > warp);
    errors.push_back(vs_exact);
    WARN("paper_single_pass w = " << w << " (rho " << o.rho(w) << "): error vs exact " << vs_exact
                                  << ", vs its closed form " << vs_closed_form);
  }
  // Amplified by ρ/(w(1 + A_eff/M)): 0.96 at w = 0.2, ~0 at w = 0.4, so the smaller fraction is the worse.
  CHECK(errors[0] > 2.0 * errors[1]);
  // One pass of the iterated scheme is the single-pass scheme, step for step.
  const Run capped = March(o, sk::TimeSchemeKind::kWeightedAverageTrapezoid, 0.2, 200, 1);
  const Run single = March(o, sk::TimeSchemeKind::kPaperSinglePass, 0.2, 200, 200);
  CHECK(capped.x == single.x);
}

TEST_CASE("stability bounds: passes |rho| < 1, single pass -1/3 < rho < 1", "[time_scheme]") {
  const Oscillator o;
  const double a_steady = o.omega * o.omega * std::abs(o.Response(o.omega));
  const auto stable = [&](const Run& r) { return r.finite && MaxAbs(r.a, 500) < 10.0 * a_steady; };
  const auto unstable = [&](const Run& r) { return !r.finite || MaxAbs(r.a, 1) > 1e6 * a_steady; };
  constexpr double kMargin = 0.02;  // "just": 2% of w either side of the bound
  // Repeated passes: fixed point iteration with factor ρ, converges for ρ > −1, i.e. w < 2/(1 + A_eff/M). Near
  // the bound the passes contract by |ρ| ≈ 0.98 each, so they get enough passes to settle (5000).
  const double w_passes = 2.0 / (1.0 + o.A_eff() / o.M);
  REQUIRE(w_passes < 1.0);
  const Run inside = March(o, sk::TimeSchemeKind::kWeightedAverageTrapezoid, w_passes * (1 - kMargin), kSteps, 5000);
  CHECK(stable(inside));
  CHECK(std::abs(Fit(inside, o.omega, kFitSamples) - o.Response(o.Warped())) / std::abs(o.Response(o.Warped())) <
        kPassesTol);
  CHECK(unstable(March(o, sk::TimeSchemeKind::kWeightedAverageTrapezoid, w_passes * (1 + kMargin), kSteps, 5000)));
  // Single pass: parasitic root of z² − 2ρz + ρ = 0 reaches z = −1 at ρ = −1/3, i.e. w = (4/3)/(1 + A_eff/M).
  const double w_single = 4.0 / 3.0 / (1.0 + o.A_eff() / o.M);
  const Run single_inside = March(o, sk::TimeSchemeKind::kPaperSinglePass, w_single * (1 - kMargin), kSteps);
  CHECK(stable(single_inside));
  CHECK(std::abs(Fit(single_inside, o.omega, kFitSamples) - o.SinglePass(w_single * (1 - kMargin))) /
            std::abs(o.SinglePass(w_single * (1 - kMargin))) <
        kSinglePassTol);
  CHECK(unstable(March(o, sk::TimeSchemeKind::kPaperSinglePass, w_single * (1 + kMargin), kSteps)));
  // So |ρ| < 1 alone does not make the single pass stable: ρ = −0.6 is inside it and diverges.
  const double w_mid = 1.6 / (1.0 + o.A_eff() / o.M);
  REQUIRE(std::fabs(o.rho(w_mid) + 0.6) < 1e-12);
  CHECK(unstable(March(o, sk::TimeSchemeKind::kPaperSinglePass, w_mid, kSteps)));
  CHECK(stable(March(o, sk::TimeSchemeKind::kWeightedAverageTrapezoid, w_mid, kSteps, 5000)));
}
