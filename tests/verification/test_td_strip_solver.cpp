// Time-domain strip solver: impulsive added mass of a semicircle against ρπR²/2, the strip kernel
// (strip_kernel_builder.h) against the marching solver (strip_marcher.h) for changing sections and several
// bodies, time-invariant against general operators, thread-count independence, forced oscillation run to a
// steady state against the steady-state transform, the free decay of a released floating cylinder, and the
// energy balance of the heave damping.
#include <algorithm>
#include <catch2/catch.hpp>

#include "support/release_march.h"
#include <cmath>
#include <complex>
#include <random>
#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "support/free_decay.h"
#include "seakeeping/sections/frequency_domain_section.h"
#include "seakeeping/green/panel.h"
#include "seakeeping/sections/section_shapes.h"
#include "seakeeping/strip/strip_kernel_builder.h"
#include "seakeeping/strip/strip_marcher.h"
#include "seakeeping/strip/strip_operators.h"
#include "seakeeping/strip/td_heave_coefficients.h"

using namespace hullopt::sk;

namespace {
constexpr double kG = 9.81;
constexpr double kRho = 1025.0;

Eigen::VectorXd HeaveNormals(const std::vector<Panel>& panels, double v = 1.0) {
  Eigen::VectorXd n(panels.size());
  for (std::size_t j = 0; j < panels.size(); ++j) n(j) = v * panels[j].Normal()[1];
  return n;
}

// A strip the hull passes through: a semicircle-like section growing and shrinking, and from step 2 on a
// second body (an outrigger) beside it, so the panel count changes from step to step.
std::vector<std::vector<Panel>> ChangingStrip(int steps) {
  std::vector<std::vector<Panel>> out;
  for (int n = 0; n < steps; ++n) {
    const double r = 0.3 + 0.5 * std::sin(M_PI * (n + 1) / (steps + 1));
    auto p = PanelSymmetricSection(LewisContour(2 * r, 0.8 * r, 0.75, 80), 8);
    if (n >= 2) {
      auto q = PanelSymmetricSection(SemicircleContour(0.15 + 0.02 * n, 60), 4, 1.5);
      p.insert(p.end(), q.begin(), q.end());
    }
    out.push_back(p);
  }
  return out;
}
// Random normal velocities at every step's collocation points (inputs for kernel-against-marcher checks).
std::vector<Eigen::VectorXd> RandomVelocities(const std::vector<std::vector<Panel>>& panels, std::mt19937& rng,
                                              std::normal_distribution<double>& normal) {
  std::vector<Eigen::VectorXd> V(panels.size());
  for (std::size_t n = 0; n < panels.size(); ++n)
    V[n] = Eigen::VectorXd::NullaryExpr(panels[n].size(), [&] { return normal(rng); });
  return V;
}
}  // namespace

TEST_CASE("impulsive added mass of a semicircle converges to rho pi R^2 / 2", "[td][verification]") {
  // Closed form (Lamb; also e.g. Korotkin, "Added Masses of Ship Structures", §5: λ33 = ½ρπR² for the
  // half-immersed circular cylinder): the t = 0+ response of the time-domain solver is the φ = 0 free-surface
  // problem. Flat constant-strength panels with the curvature term of their self influence (rankine_panel.h)
  // converge at second order (measured −1.1%, −0.27%, −0.06%, −0.02% at 14–112 panels; without the term
  // first order, +6.3% at 14), so the required 1% holds from 28 panels, and Richardson extrapolation
  // (4a(2N) − a(N))/3 removes the O(1/N²) term.
  constexpr double kTolHighFrequency = 0.01;  // required: within 1% of ρπR²/2
  constexpr double kTolExtrapolated = 5e-4;   // O(1/N³) remainder after removing the O(1/N²) term
  const double R = 1.3, m0 = kRho * M_PI * R * R / 2;
  std::vector<double> a;
  for (int np : {14, 28, 56, 112}) {
    const auto panels = PanelSymmetricSection(SemicircleContour(R, 2000), np);
    const auto ops = BuildFixedSectionOperators(panels, 1, 0.01, kRho, kG);
    a.push_back(-ops.MomentumCurrent(0).dot(ops.Solve(0, HeaveNormals(panels)).col(0)) / m0);
    WARN("semicircle, " << np << " panels: a33(t=0+)/(rho pi R^2/2) = " << a.back());
  }
  CHECK(std::fabs(a[1] - 1.0) <= kTolHighFrequency);
  CHECK(std::fabs((4 * a[3] - a[2]) / 3 - 1.0) <= kTolExtrapolated);
  // Monotone second-order convergence: each doubling quarters the error (ratio 4 ± 0.6).
  for (int i = 0; i + 2 < 4; ++i) CHECK((a[i] - a[i + 1]) / (a[i + 1] - a[i + 2]) == Approx(4.0).margin(0.6));
}

TEST_CASE("strip kernel reproduces the marching solver for changing sections and two bodies",
          "[td][kernel]") {
  constexpr double kTolKernel = 1e-9;  // same arithmetic reordered: round-off only
  const int N = 7;
  const auto panels = ChangingStrip(N);
  const double dt = 0.04;
  const auto ops = BuildStripOperators(panels, dt, kRho, kG);
  std::vector<double> x(N);
  for (int n = 0; n < N; ++n) x[n] = 10.0 - 0.8 * n;
  const StripKernel K = BuildStripKernel(ops, x);
  REQUIRE(K.Steps() == N);
  CHECK(K.speed_m_s == Approx(0.8 / dt));
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 2; ++trial) {
    const std::vector<Eigen::VectorXd> V = RandomVelocities(panels, rng, normal);
    StripMarcher marcher(ops);
    for (int n = 0; n < N; ++n) {
      const double f_march = marcher.Advance(V[n]);
      double f_kernel = 0;
      for (int m = 0; m <= n; ++m) f_kernel += K.force[n][m].dot(V[m]);
      CHECK(f_kernel == Approx(f_march).epsilon(kTolKernel).margin(kTolKernel * 1e4));
    }
  }
}

TEST_CASE("a strip may hold no section at some steps (before the bow, after the stern)", "[td][kernel]") {
  constexpr double kTolKernel = 1e-9;  // round-off only
  auto panels = ChangingStrip(4);
  panels.insert(panels.begin(), std::vector<Panel>{});
  panels.push_back({});
  const auto ops = BuildStripOperators(panels, 0.05, kRho, kG);
  const StripKernel K = BuildStripKernel(ops, {5, 4, 3, 2, 1, 0});
  StripMarcher marcher(ops);
  std::vector<Eigen::VectorXd> V;
  for (std::size_t n = 0; n < panels.size(); ++n) {
    V.push_back(HeaveNormals(panels[n], 0.3 + 0.1 * n));
    const double f_march = marcher.Advance(V.back());
    double f_kernel = 0;
    for (std::size_t m = 0; m <= n; ++m) f_kernel += K.force[n][m].dot(V[m]);
    CHECK(std::isfinite(f_march));
    CHECK(f_kernel == Approx(f_march).epsilon(kTolKernel).margin(kTolKernel * 1e4));
  }
}

TEST_CASE("time-invariant operators equal the general operators of an unchanging section", "[td]") {
  constexpr double kTolSame = 1e-12;  // identical formulas, different bookkeeping
  const auto panels = PanelSymmetricSection(SemicircleContour(0.7), 10);
  const int N = 5;
  const auto fixed = BuildFixedSectionOperators(panels, N, 0.05, kRho, kG);
  const auto general = BuildStripOperators(std::vector<std::vector<Panel>>(N, panels), 0.05, kRho, kG);
  for (int n = 0; n < N; ++n) {
    CHECK((fixed.System(n) - general.System(n)).norm() <= kTolSame * general.System(n).norm());
    CHECK((fixed.MomentumCurrent(n) - general.MomentumCurrent(n)).norm() <=
          kTolSame * general.MomentumCurrent(n).norm());
    for (int k = 0; k < n; ++k) {
      CHECK((fixed.Memory(n, k) - general.Memory(n, k)).norm() <=
            kTolSame * (1 + general.Memory(n, k).norm()));
      CHECK((fixed.MomentumMemory(n, k) - general.MomentumMemory(n, k)).norm() <=
            kTolSame * (1 + general.MomentumMemory(n, k).norm()));
    }
  }
}

#ifdef _OPENMP
TEST_CASE("operators are bitwise identical with 1 and 2 threads", "[td][openmp]") {
  const auto panels = ChangingStrip(6);
  omp_set_num_threads(1);
  const auto one = BuildStripOperators(panels, 0.05, kRho, kG);
  omp_set_num_threads(2);
  const auto two = BuildStripOperators(panels, 0.05, kRho, kG);
  for (int n = 0; n < 6; ++n) {
    CHECK(one.System(n) == two.System(n));
    CHECK(one.MomentumCurrent(n) == two.MomentumCurrent(n));
    for (int k = 0; k < n; ++k) {
      CHECK(one.Memory(n, k) == two.Memory(n, k));
      CHECK(one.MomentumMemory(n, k) == two.MomentumMemory(n, k));
    }
  }
}
#endif

TEST_CASE("forced heave run to steady state agrees with the steady-state transform", "[td][verification]") {
  // The marching solver (BDF2 force from the momentum history, started from rest) against the periodic steady
  // state of the same discretisation summed over lags (SteadyHeaveMomentum), both on the same operators.
  // The source formulation rings undamped at its irregular frequency (ω²R/g ≈ 1.8 for the semicircle, excited
  // by the impulsive start), so the harmonic is fitted over the last 6 periods (~2 beat periods), which
  // leaves ~0.5% of that ringing; the BDF2 derivative adds (ωdt)²/3 ≈ 0.8% at 40 steps per period.
  constexpr double kTolSteady = 0.02;
  const double R = 1.0, w = std::sqrt(1.0 * kG / R), m0 = kRho * M_PI * R * R / 2;
  const auto panels = PanelSymmetricSection(SemicircleContour(R), 14);
  const int per_period = 40, periods = 12, N = per_period * periods;
  const double dt = 2 * M_PI / w / per_period;
  const auto ops = BuildFixedSectionOperators(panels, N, dt, kRho, kG);
  const std::complex<double> I = SteadyHeaveMomentum(ops, w, N - 1);
  const double a_ss = -I.real(), b_ss = w * I.imag();
  StripMarcher marcher(ops);
  std::vector<double> f(N);
  for (int n = 0; n < N; ++n) f[n] = marcher.Advance(HeaveNormals(panels, std::cos(w * n * dt)));
  // Fit f = −a33 ẍ − b33 ẋ with ẋ = cos ωt (ẍ = −ω sin ωt): f = a33 ω sin ωt − b33 cos ωt.
  const int fit = 6 * per_period;
  double s_sin = 0, s_cos = 0;
  for (int n = N - fit; n < N; ++n) {
    s_sin += f[n] * std::sin(w * n * dt) * 2.0 / fit;
    s_cos += f[n] * std::cos(w * n * dt) * 2.0 / fit;
  }
  const double a33 = s_sin / w, b33 = -s_cos;
  WARN("forced heave at w^2R/g = 1 (14 panels): marching a33/m0 = "
       << a33 / m0 << ", b33/(m0 w) = " << b33 / (m0 * w) << "; steady-state transform " << a_ss / m0 << ", "
       << b_ss / (m0 * w));
  const double scale = std::hypot(a_ss * w, b_ss);
  CHECK(std::fabs(a33 - a_ss) * w <= kTolSteady * scale);
  CHECK(std::fabs(b33 - b_ss) <= kTolSteady * scale);
}

namespace {
// Released half-immersed circular cylinder of radius R: mass ρπR²/2, restoring C = ρgB = 2ρgR.
struct Release {
  double R = 1.0, m = kRho * M_PI / 2, C = 2 * kRho * kG;
};

std::vector<double> ReleaseHistory(const StripOperators& ops, const std::vector<Panel>& panels,
                                   const Release& body, int N) {
  return hullopt::testing::ReleaseHistory(ops, panels, body.m, body.C, N);
}

using hullopt::testing::DecayMeasures;
using hullopt::testing::MeasureDecay;
using hullopt::testing::Times;
}  // namespace

TEST_CASE("free decay of a released cylinder: marching against the transform of the same discretisation",
          "[td][verification]") {
  // Self-consistency of the time-domain route: the release history against linear theory (free_decay.h),
  // x/x0 = 1 − (2C/π)∫ Re H sin(ωt)/ω dω, with a33(ω), b33(ω) from the steady-state transform of the SAME
  // operators at 240 frequencies. (The prediction from the frequency-domain solver: next test.)
  // Also the single-frequency damped-oscillator estimate, only approximate for ζ ≈ 0.17 (reported).
  // Second cycle (reported, not checked): 1.062 (march) vs 1.027 (transform). Not the time step (march 1.069,
  // 1.062, 1.061 at dt = 0.04, 0.02, 0.01 s), not the Fourier integral (dω 0.05 → 0.0125 rad/s or range
  // 12 → 30 rad/s: < 5e−4), but the irregular frequency: the release excites the interior mode of the
  // source formulation, which rings undamped in the march (amplitude 0.0070 x0 at ω²R/g = 1.885, still there
  // after 30 s), while the transform sees it only as a sampled near-pole of a33, b33 (ω²R/g = 1.80–1.88).
  // That ringing is 7% of the second peak (0.106 x0). It is excited by the discretisation: 0.0070, 0.0032,
  // 0.0017 x0 at 14, 28, 56 panels.
  constexpr double kTolPeriod = 0.03;        // required: period and log decrement within 3%
  constexpr double kTolLogDecrement = 0.03;  // first cycle
  constexpr double kTolHistory = 0.03;  // max |Δx|/x0 over the first 3 periods: BDF2 phase error ~(ωdt)³
                                        // plus the 0.007 x0 ringing
  const Release body;
  const double dt = 0.02;
  const auto panels = PanelSymmetricSection(SemicircleContour(body.R), 14);
  const int N = 400, N_ops = 1500;  // 8 s of motion; 30 s of memory for the transform
  const auto ops = BuildFixedSectionOperators(panels, N_ops, dt, kRho, kG);
  const Eigen::VectorXd nz = HeaveNormals(panels);
  const std::vector<double> xs = ReleaseHistory(ops, panels, body, N), t = Times(N, dt);
  FreeDecayInput fd;
  for (int i = 0; i < 240; ++i) {
    const double w = 0.1 + 0.05 * i;
    const std::complex<double> I = SteadyHeaveMomentum(ops, w, N_ops - 1);
    fd.omega_rad_s.push_back(w);
    fd.a33_kg_per_m.push_back(-I.real());
    fd.b33_kg_per_m_s.push_back(w * I.imag());
  }
  fd.a33_infinite_kg_per_m = -ops.MomentumCurrent(0).dot(ops.Solve(0, nz).col(0));
  fd.mass_kg_per_m = body.m;
  fd.restoring_n_per_m2 = body.C;
  const std::vector<double> predicted = FreeDecayFromCoefficients(fd, t);
  const DecayMeasures td = MeasureDecay(xs, dt), fdm = MeasureDecay(predicted, dt);
  double max_diff = 0;
  for (int n = 0; n < N && t[n] < 3 * td.period; ++n)
    max_diff = std::max(max_diff, std::fabs(xs[n] - predicted[n]));
  // Single-frequency estimate at the undamped natural frequency ω_n = sqrt(C/(m + a33(ω_n))).
  const double m = body.m, C = body.C;
  double w = std::sqrt(C / (2 * m));
  std::complex<double> I;
  for (int it = 0; it < 30; ++it) {
    I = SteadyHeaveMomentum(ops, w, N_ops - 1);
    w = std::sqrt(C / (m - I.real()));
  }
  const double zeta = w * I.imag() / (2 * (m - I.real()) * w);
  WARN("released cylinder (14 panels, dt = 0.02 s): period "
       << td.period << " s (time domain) vs " << fdm.period
       << " s (transform of the time-domain operators); log decrement " << td.logdec << " vs " << fdm.logdec
       << " (next cycle " << td.logdec_second << " vs " << fdm.logdec_second << ")"
       << "; max |dx|/x0 over 3 periods " << max_diff << "; single-frequency oscillator: period "
       << 2 * M_PI / (w * std::sqrt(1 - zeta * zeta)) << " s, log decrement "
       << 2 * M_PI * zeta / std::sqrt(1 - zeta * zeta));
  CHECK(td.period == Approx(fdm.period).epsilon(kTolPeriod));
  CHECK(td.logdec == Approx(fdm.logdec).epsilon(kTolLogDecrement));
  CHECK(max_diff <= kTolHistory);
}

TEST_CASE("free decay of a released cylinder against the frequency-domain solver's coefficients",
          "[td][fd][verification]") {
  // The time-domain release history (marching, no frequency-domain input) against the
  // history linear theory predicts from the FREQUENCY-DOMAIN panel solver's a33(ω), b33(ω)
  // (SolveSectionFrequencyDomain with its lid on, so the curve has no irregular frequency), same panels.
  // Infinite-frequency added mass (used beyond the last frequency, 12 rad/s, where |C H| < 0.05, falling as
  // ω⁻²): the frequency-domain solver at ω²R/g = 200.
  // The frequency-domain coefficients carry the O(1/N) error of flat constant panels (lid on, 14 panels: a33
  // +4.7%, b33 +3.5% against Ursell at ω²R/g = 0.25, lid off +5.4%, +2.2%;
  // tests/verification/test_frequency_domain_section.cpp prints them). The first-cycle log decrement of the
  // lid-on prediction is 1.248, 1.216, 1.202 at 14, 28, 56 panels (Richardson 1.188) against the march's
  // 1.180, 1.185, 1.188, so the required 3% is met from 56 panels on: checked there, 14 and 28 reported. Time
  // step 0.02 s: halving it moves the march's figures by < 0.2%.
  constexpr double kTolPeriod = 0.03;        // required: within 3%
  constexpr double kTolLogDecrement = 0.03;  // required: within 3%, first and second cycle
  constexpr int kPanelsChecked = 56;
  const Release body;
  const double dt = 0.02;
  const int N = 400;  // 8 s: three and a half periods
  // Frequencies: 0.1 rad/s steps to 6 rad/s (ω_n ≈ 2.8 rad/s, the transfer function's peak), 0.5 to 12 rad/s.
  std::vector<double> w;
  for (int i = 0; i < 60; ++i) w.push_back(0.1 + 0.1 * i);
  for (double ww = 6.5; ww <= 12.0 + 1e-9; ww += 0.5) w.push_back(ww);
  FrequencyDomainOptions fo;
  fo.rho_kg_m3 = kRho, fo.g_m_s2 = kG;  // lid automatic (on)
  for (int np : {14, 28, 56}) {
    const auto panels = PanelSymmetricSection(SemicircleContour(body.R), np);
    const auto ops = BuildFixedSectionOperators(panels, N, dt, kRho, kG);
    const std::vector<double> xs = ReleaseHistory(ops, panels, body, N);
    FreeDecayInput in;
    in.omega_rad_s = w;
    for (const auto& h : SolveSectionFrequencyDomain({panels}, w, fo))
      in.a33_kg_per_m.push_back(h.a33()), in.b33_kg_per_m_s.push_back(h.b33());
    in.a33_infinite_kg_per_m = SolveSectionFrequencyDomain({panels}, std::sqrt(200 * kG / body.R), fo).a33();
    in.mass_kg_per_m = body.m;
    in.restoring_n_per_m2 = body.C;
    const DecayMeasures td = MeasureDecay(xs, dt),
                        fd = MeasureDecay(FreeDecayFromCoefficients(in, Times(N, dt)), dt);
    WARN("released cylinder, " << np << " panels, dt = " << dt << " s: period " << td.period
                               << " s (time domain) vs " << fd.period
                               << " s (frequency-domain solver, lid on); log decrement " << td.logdec
                               << " vs " << fd.logdec << ", second cycle " << td.logdec_second << " vs "
                               << fd.logdec_second);
    if (np != kPanelsChecked) continue;
    CHECK(td.period == Approx(fd.period).epsilon(kTolPeriod));
    CHECK(td.logdec == Approx(fd.logdec).epsilon(kTolLogDecrement));
    CHECK(td.logdec_second == Approx(fd.logdec_second).epsilon(kTolLogDecrement));
  }
}

TEST_CASE("heave damping equals the radiated wave energy flux", "[td][verification]") {
  // Energy balance: b33 from the force (momentum route) against
  // ρg²(|A+|² + |A−|²)/(2ω) from the far-field wave amplitudes of the same steady-state sources. The two use
  // different parts of the solution (near-field potential on the body vs the sources' wave-number transform),
  // so they agree only to the O(1/N) error of flat constant panels (docs/theory.md): the mismatch halves with
  // each doubling of the panels (measured 3–5% at 14, 1–3% at 28, ≤ 1.5% at 56 panels), so the required 2% is
  // checked at 56 panels and the 14- and 28-panel ratios are reported. Halving the time step changes the
  // ratios by < 1e−3.
  // Frequencies avoid the irregular band around ω²R/g ≈ 1.8 (docs/theory.md).
  constexpr double kTolEnergy = 0.02;  // required: within 2%
  constexpr int kPanelsChecked = 56;
  const double R = 1.0;
  const std::vector<double> nondim = {0.25, 0.5, 0.75, 1.0, 2.5};
  const double w_max = std::sqrt(nondim.back() * kG / R);
  const double dt = 2 * M_PI / w_max / 40;
  const int lags = static_cast<int>(20.0 / dt);  // 20 s ≈ 64 sqrt(R/g): near-surface memory decayed by e^{−6}
  for (int np : {14, 28, 56}) {
    const auto panels = PanelSymmetricSection(SemicircleContour(R), np);
    const auto ops =
        BuildFixedSectionOperators(panels, lags + 1, dt, kRho, kG, {}, /*steady_state_only=*/true);
    for (double k : nondim) {
      const double w = std::sqrt(k * kG / R);
      const double b33 = w * SteadyHeaveMomentum(ops, w, lags).imag();
      const auto A = FarFieldWaveAmplitudes(panels, SteadyHeaveSources(ops, w, lags), w, kG);
      const double b_energy = kRho * kG * kG * (A[0] * A[0] + A[1] * A[1]) / (2 * w);
      WARN(np << " panels, w^2R/g = " << k << ": b33 = " << b33 << " kg/(m s), energy flux " << b_energy
              << ", ratio " << b33 / b_energy);
      if (np == kPanelsChecked) CHECK(b33 == Approx(b_energy).epsilon(kTolEnergy));
    }
  }
}

TEST_CASE("pressure-form sectional force: equals the momentum form for a section that does not change",
          "[td][kernel][pressure]") {
  // For a contour that stays put, ∫φ_t n_z dl at fixed points IS d/dt ∫φ n_z dl: the pressure form's rows
  // (earlier potentials evaluated on the current contour, computed separately from the momentum rows) must
  // reproduce the momentum form to round-off. Two bodies, so the cross-body memory enters too.
  constexpr double kTolIdentity = 1e-9;  // same physics through different operator rows: round-off only
  const int N = 8;
  auto a = PanelSymmetricSection(SemicircleContour(0.7), 8, -1.5);
  const auto b = PanelSymmetricSection(SemicircleContour(0.7), 8, 1.5);
  a.insert(a.end(), b.begin(), b.end());
  const std::vector<std::vector<Panel>> panels(N, a);
  std::vector<double> x(N);
  for (int n = 0; n < N; ++n) x[n] = 10.0 - 0.4 * n;
  StripOperatorOptions momentum, pressure;
  pressure.sectional_force = SectionalForce::kPressure;
  const StripKernel Km = BuildStripKernel(panels, x, 0.05, kRho, kG, momentum);
  const StripKernel Kp = BuildStripKernel(panels, x, 0.05, kRho, kG, pressure);
  for (int n = 0; n < N; ++n)
    for (int m = 0; m <= n; ++m)
      for (Eigen::Index j = 0; j < Km.force[n][m].size(); ++j)
        CHECK(Kp.force[n][m](j) == Approx(Km.force[n][m](j)).epsilon(kTolIdentity).margin(kTolIdentity * 1e4));
}

TEST_CASE("pressure-form sectional force: strip kernel reproduces the marching solver for changing sections",
          "[td][kernel][pressure]") {
  constexpr double kTolKernel = 1e-9;  // same arithmetic reordered: round-off only
  const int N = 7;
  const auto panels = ChangingStrip(N);
  const double dt = 0.04;
  StripOperatorOptions o;
  o.sectional_force = SectionalForce::kPressure;
  const auto ops = BuildStripOperators(panels, dt, kRho, kG, o);
  std::vector<double> x(N);
  for (int n = 0; n < N; ++n) x[n] = 10.0 - 0.8 * n;
  const StripKernel K = BuildStripKernel(ops, x);
  const StripKernel Km = BuildStripKernel(panels, x, dt, kRho, kG, StripOperatorOptions{});
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  const std::vector<Eigen::VectorXd> V = RandomVelocities(panels, rng, normal);
  StripMarcher marcher(ops);
  double differs = 0;  // the two forms must differ where the sections change (else the option does nothing)
  for (int n = 0; n < N; ++n) {
    const double f_march = marcher.Advance(V[n]);
    double f_kernel = 0, f_momentum = 0;
    for (int m = 0; m <= n; ++m) f_kernel += K.force[n][m].dot(V[m]), f_momentum += Km.force[n][m].dot(V[m]);
    CHECK(f_kernel == Approx(f_march).epsilon(kTolKernel).margin(kTolKernel * 1e4));
    differs = std::max(differs, std::fabs(f_kernel - f_momentum) / std::max(std::fabs(f_momentum), 1.0));
  }
  CHECK(differs > 1e-3);
}
