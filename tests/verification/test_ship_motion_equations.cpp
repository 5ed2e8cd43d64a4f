// Ship equations of motion (heave/pitch in head seas) over hand-built strip kernels on a wall-sided box,
// against the continuous closed form of the same equations, the static limit, and between the two solution
// paths (periodic steady state 2b vs time marching 2a).
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>

#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/motions/head_sea_wave.h"
#include "seakeeping/motions/periodic_motion_solver.h"
#include "seakeeping/strip/strip_force_model.h"
#include "seakeeping/motions/strip_theory_stf.h"
#include "seakeeping/motions/time_marching_motion.h"
#include "support/box_strip_kernel.h"

namespace sk = hullopt::sk;
using cd = std::complex<double>;
using hullopt::testing::BoxHull;
using hullopt::testing::BoxKernel;

namespace {

hullopt::hull::MassProperties BoxMass(const BoxHull& h) {
  hullopt::hull::MassProperties m;
  m.mass_kg = h.rho * h.L * h.B * h.T;
  m.lcg_m_from_ap = 0.5 * h.L;
  m.kyy_m = 0.25 * h.L;
  return m;
}

// Composite Simpson over [a, b] with n (even) intervals; the integrands are smooth, 2000 intervals give
// ~1e-13.
cd Integrate(const std::function<cd(double)>& f, double a, double b, int n = 2000) {
  const double h = (b - a) / n;
  cd s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return s * h / 3.0;
}

// The continuous equations of the box with a constant added mass a in momentum form (see box_strip_kernel.h):
// section force −(ρg + c iω_e)B s − cBU X5 + (ρg e^{−kT} + c iω)B e^{ikx}, c = ½CsρU; kernel force
// −a(iω_e − U∂x)ũ with the bow impulse −aUũ(bow), ũ = iω_e(X3 − xX5) + UX5 − iω e^{−kT} e^{ikx}.
// Integrated by parts: F3,kernel = −a iω_e ∫ũ − aU ũ(stern), F5,kernel = a iω_e ∫xũ + aU x_s ũ(stern) + aU
// ∫ũ.
// a may be complex: a frequency-domain impedance Z = a33 + b33/(iω_e), constant along the box.
std::pair<cd, cd> ContinuousRao(const BoxHull& h, cd a, double cs, double w) {
  const double U = h.speed, g = h.g, rho = h.rho, B = h.B, T = h.T;
  const double we = w + w * w * U / g, k = w * w / g, c = 0.5 * cs * rho * U;
  const double xs = -0.5 * h.L, xb = 0.5 * h.L;
  const cd I(0, 1), q = rho * g + c * I * we;
  const double M = rho * h.L * B * T, I5 = M * std::pow(0.25 * h.L, 2);
  // Unknown-by-unknown: column j of (F3, F5) per unit X3 (j = 0), X5 (j = 1) and A (j = 2).
  std::function<cd(double)> u[3] = {
      [&](double) { return I * we; }, [&](double x) { return -I * we * x + U; },
      [&](double x) { return -I * w * std::exp(-k * T) * std::exp(I * k * x); }};
  std::function<cd(double)> sec[3] = {
      [&](double) { return -q * B; }, [&](double x) { return q * B * x - c * B * U; },
      [&](double x) { return (rho * g * std::exp(-k * T) + c * I * w) * B * std::exp(I * k * x); }};
  cd F3[3], F5[3];
  for (int j = 0; j < 3; ++j) {
    const cd iu = Integrate(u[j], xs, xb), ixu = Integrate([&](double x) { return x * u[j](x); }, xs, xb);
    F3[j] = Integrate(sec[j], xs, xb) - a * I * we * iu - a * U * u[j](xs);
    F5[j] = -Integrate([&](double x) { return x * sec[j](x); }, xs, xb) + a * I * we * ixu +
            a * U * xs * u[j](xs) + a * U * iu;
  }
  Eigen::Matrix2cd A;
  A << -we * we * M - F3[0], -F3[1], -F5[0], -we * we * I5 - F5[1];
  const Eigen::Vector2cd X = A.fullPivLu().solve(Eigen::Vector2cd(F3[2], F5[2]));
  return {X[0], X[1] / k};
}

std::vector<double> OmegaFromEncounter(const std::vector<double>& we, double U, double g) {
  std::vector<double> w;
  for (double e : we) w.push_back(sk::HeadSeaWaveFrequency(e, U, g));
  return w;
}

}  // namespace

TEST_CASE("periodic path reproduces the continuous box equations", "[motions][periodic]") {
  BoxHull h;
  h.sections =
      400;  // midpoint sums of the zero kernel converge as (kΔx)²; the momentum kernel's ends as Δx/L
  const double cs = 0.1;
  std::vector<double> we;
  for (double e = 0.5; e <= 10.0; e += 0.5) we.push_back(e);
  const auto w = OmegaFromEncounter(we, h.speed, h.g);
  for (double a : {0.0, 400.0, 1500.0}) {  // added mass per length: none, A/M ≈ 0.8, A/M ≈ 2.9
    const auto kernel = BoxKernel(h, a);
    sk::MotionOptions opt;
    opt.damping_cs = cs;
    const sk::HeadSeaShipModel model(kernel, BoxMass(h), opt);
    const auto rao = sk::SolvePeriodicRaos(model, w);
    double peak3 = 0, peak5 = 0;
    std::vector<std::pair<cd, cd>> ref;
    for (double wi : w) {
      ref.push_back(ContinuousRao(h, a, cs, wi));
      peak3 = std::max(peak3, std::abs(ref.back().first));
      peak5 = std::max(peak5, std::abs(ref.back().second));
    }
    // Zero kernel: only midpoint-rule error, (kΔx)²/24 < 1e-5. Momentum kernel: the discrete bow/stern ends
    // differ from the continuous ones by O(Δx/L) = 0.25%; 1% of the peak leaves room.
    const double tol = a == 0.0 ? 1e-4 : 1e-2;
    for (std::size_t i = 0; i < w.size(); ++i) {
      INFO("a = " << a << " omega_e = " << we[i]);
      CHECK(std::abs(rao.heave[i] - ref[i].first) < tol * peak3);
      CHECK(std::abs(rao.pitch[i] - ref[i].second) < tol * peak5);
    }
  }
}

TEST_CASE("static limit: heave and pitch RAOs tend to 1 as omega -> 0", "[motions][limits]") {
  BoxHull h;
  for (double a : {0.0, 400.0}) {
    const auto kernel = BoxKernel(h, a);
    sk::MotionOptions opt;
    opt.damping_cs = 0.05;
    const sk::HeadSeaShipModel model(kernel, BoxMass(h), opt);
    const auto rao = sk::SolvePeriodicRaos(model, {0.02});
    // At ω = 0.02 rad/s (kL = 4e-4) the dynamic and e^{−kT} corrections are O(kL) ~ 1e-3.
    constexpr double kStaticTol = 5e-3;
    CHECK(std::abs(rao.heave[0] - 1.0) < kStaticTol);
    // Pitch bow-down following the wave slope: X5 = −ikA, so X5/(kA) = −i.
    CHECK(std::abs(rao.pitch[0] - cd(0, -1)) < kStaticTol);
  }
}

TEST_CASE("time marching agrees with the periodic steady state", "[motions][marching]") {
  BoxHull h;
  h.sections = 40;
  const std::vector<double> we = {1.0, 2.0, 3.0, 3.5, 4.0, 5.0, 7.0};
  const auto w = OmegaFromEncounter(we, h.speed, h.g);
  for (double a : {0.0, 400.0, 1500.0}) {
    const auto kernel = BoxKernel(h, a);
    sk::MotionOptions opt;
    opt.damping_cs = 0.1;
    const sk::HeadSeaShipModel model(kernel, BoxMass(h), opt);
    const auto periodic = sk::SolvePeriodicRaos(model, w);
    sk::KernelStripForceModel forces(kernel);
    sk::MarchingOptions mo;
    const auto marched = sk::SolveMarchingRaos(model, forces, w, mo);
    double peak3 = 0, peak5 = 0;
    for (std::size_t i = 0; i < w.size(); ++i) {
      peak3 = std::max(peak3, std::abs(periodic.heave[i]));
      peak5 = std::max(peak5, std::abs(periodic.pitch[i]));
    }
    // Path agreement: magnitudes within 1% of the peak, phases within 3 degrees. The marching differs by
    // its trapezoid/extrapolation error O((ω_e Δt)²) ≈ 0.3% at ω_e Δt = 0.22.
    constexpr double kAmpTol = 0.01, kPhaseTolDeg = 3.0;
    for (std::size_t i = 0; i < w.size(); ++i) {
      INFO("a = " << a << " omega_e = " << we[i] << " periodic " << periodic.heave[i] << " "
                  << periodic.pitch[i] << " marched " << marched.heave[i] << " " << marched.pitch[i]);
      CHECK(std::abs(std::abs(marched.heave[i]) - std::abs(periodic.heave[i])) < kAmpTol * peak3);
      CHECK(std::abs(std::abs(marched.pitch[i]) - std::abs(periodic.pitch[i])) < kAmpTol * peak5);
      CHECK(std::abs(std::arg(marched.heave[i] / periodic.heave[i])) * 180 / M_PI < kPhaseTolDeg);
      CHECK(std::abs(std::arg(marched.pitch[i] / periodic.pitch[i])) * 180 / M_PI < kPhaseTolDeg);
    }
  }
}

TEST_CASE("weighted average: explicit update diverges when added mass exceeds ship mass",
          "[motions][marching]") {
  BoxHull h;
  h.sections = 40;
  // A/M ≈ 2.9 (docs/theory.md, 'Weighted-average acceleration (averaging method)': w = 1 unstable for A > M)
  const auto kernel = BoxKernel(h, 1500.0);
  sk::MotionOptions opt;
  opt.damping_cs = 0.1;
  const sk::HeadSeaShipModel model(kernel, BoxMass(h), opt);
  sk::KernelStripForceModel forces(kernel);
  const std::vector<double> w = {sk::HeadSeaWaveFrequency(3.0, h.speed, h.g)};
  sk::MarchingOptions explicit_update;
  explicit_update.hydrodynamic_fraction = 1.0;
  explicit_update.max_passes = 1;
  CHECK_THROWS_AS(sk::SolveMarchingRaos(model, forces, w, explicit_update), std::domain_error);
  sk::MarchingOptions paper;  // single pass, w = 0.2: stable
  paper.max_passes = 1;
  CHECK_NOTHROW(sk::SolveMarchingRaos(model, forces, w, paper));
}

TEST_CASE("bad inputs to the ship equations are refused", "[motions][errors]") {
  BoxHull h;
  h.sections = 10;
  auto kernel = BoxKernel(h, 0.0);
  sk::MotionOptions opt;
  opt.hull_name = "box";
  auto mass = BoxMass(h);
  CHECK_NOTHROW(sk::HeadSeaShipModel(kernel, mass, opt));
  {
    auto k0 = kernel;
    k0.speed_m_s = 0.0;
    CHECK_THROWS_WITH(sk::HeadSeaShipModel(k0, mass, opt),
                      Catch::Contains("speed") && Catch::Contains("> 0"));
    k0.speed_m_s = -3.0;
    CHECK_THROWS_AS(sk::HeadSeaShipModel(k0, mass, opt), std::invalid_argument);
  }
  opt.damping_cs = -0.1;
  CHECK_THROWS_WITH(sk::HeadSeaShipModel(kernel, mass, opt), Catch::Contains("Cs"));
  opt.damping_cs = 0.0;
  mass.mass_kg = 0.0;
  CHECK_THROWS_WITH(sk::HeadSeaShipModel(kernel, mass, opt), Catch::Contains("mass"));
  mass = BoxMass(h);
  const sk::HeadSeaShipModel model(kernel, mass, opt);
  CHECK_THROWS_AS(sk::SolvePeriodicRaos(model, {}), std::invalid_argument);
  CHECK_THROWS_AS(sk::SolvePeriodicRaos(model, {1.0, -2.0}), std::invalid_argument);
  // A kernel with a non-finite entry gives a non-finite result: reported with hull and frequency, not
  // written.
  auto bad = kernel;
  bad.force[3][1][0] = std::numeric_limits<double>::quiet_NaN();
  const sk::HeadSeaShipModel bad_model(bad, mass, opt);
  CHECK_THROWS_WITH(sk::SolvePeriodicRaos(bad_model, {1.5}), Catch::Contains("hull 'box'") &&
                                                                 Catch::Contains("non-finite") &&
                                                                 Catch::Contains("omega = 1.5"));
  sk::MarchingOptions mo;
  mo.hydrodynamic_fraction = 0.0;
  std::string err;
  CHECK_FALSE(mo.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("hydrodynamic_fraction"));
  mo.hydrodynamic_fraction = 1.5;
  CHECK_FALSE(mo.IsValid(&err));
}

TEST_CASE("irregular sea: marched time series is the superposition of periodic RAO responses",
          "[motions][marching][irregular]") {
  BoxHull h;
  h.sections = 40;
  const auto kernel = BoxKernel(h, 400.0);
  sk::MotionOptions opt;
  opt.damping_cs = 0.1;
  const sk::HeadSeaShipModel model(kernel, BoxMass(h), opt);
  const std::vector<sk::WaveComponent> sea = {{0.3, 1.2, 0.4}, {0.2, 1.6, 2.1}, {0.1, 2.2, -1.0}};
  std::vector<double> w;
  for (const auto& c : sea) w.push_back(c.omega_rad_s);
  const auto rao = sk::SolvePeriodicRaos(model, w);
  sk::KernelStripForceModel forces(kernel);
  const double duration = 80.0, ramp = 10.0;
  const auto ts = sk::MarchHeadSea(model, forces, sea, duration, ramp, sk::MarchingOptions{});
  double max3 = 0, max5 = 0, err3 = 0, err5 = 0;
  for (std::size_t i = 0; i < ts.t_s.size(); ++i) {
    if (ts.t_s[i] < 50.0) continue;  // ramp and start-up transient (decay time ~ 10 s) over
    double x3 = 0, x5 = 0;
    for (std::size_t j = 0; j < sea.size(); ++j) {
      const double we = sk::HeadSeaEncounterFrequency(sea[j].omega_rad_s, h.speed, h.g);
      const cd e = std::polar(sea[j].amplitude_m, we * ts.t_s[i] + sea[j].phase_rad);
      x3 += (rao.heave[j] * e).real();
      x5 += (rao.pitch[j] * (w[j] * w[j] / h.g) * e).real();
    }
    max3 = std::max(max3, std::fabs(x3));
    max5 = std::max(max5, std::fabs(x5));
    err3 = std::max(err3, std::fabs(ts.heave_m[i] - x3));
    err5 = std::max(err5, std::fabs(ts.pitch_rad[i] - x5));
  }
  // Trapezoid warp (ω_e Δt)²/12 < 0.1% here, plus the decayed transient: 2% of the largest excursion.
  constexpr double kSeriesTol = 0.02;
  CHECK(err3 < kSeriesTol * max3);
  CHECK(err5 < kSeriesTol * max5);
  // The wave record at the CG is the sum of the components once the ramp is over.
  const std::size_t last = ts.t_s.size() - 1;
  double z = 0;
  for (const auto& c : sea)
    z += c.amplitude_m *
         std::cos(sk::HeadSeaEncounterFrequency(c.omega_rad_s, h.speed, h.g) * ts.t_s[last] + c.phase_rad);
  CHECK(ts.wave_at_cg_m[last] == Approx(z).margin(1e-12));
}

TEST_CASE("strip theory (STF) path: the momentum kernel to its lag error, and the continuous closed form with damping",
          "[motions][stf]") {
  BoxHull h;
  h.sections = 400;
  const double a = 400.0, b = 900.0, cs = 0.1;  // b: a constant 2D heave damping [kg/(m s)]
  const auto geometry = BoxKernel(h, 0.0);
  sk::MotionOptions opt;
  opt.damping_cs = cs;
  const sk::HeadSeaShipModel model(geometry, BoxMass(h), opt);
  std::vector<double> we;
  for (double e = 1.0; e <= 9.0; e += 1.0) we.push_back(e);
  const auto w = OmegaFromEncounter(we, h.speed, h.g);
  // (1) b = 0: the box momentum kernel's rows are the first-order time difference of the strip momentum,
  // (J_n − e^{−iω_e Δt} J_{n−1})/Δt, whose phase error ω_e Δt/2 strip theory does not have (its time derivative
  // is exact, strip_theory_stf.h): the two agree to that error, ω_e Δt ≤ 0.03 here, of the peak.
  const auto stf0 = sk::SolveStripTheoryRaos(model, w, [&](int n, double omega_e) {
    return sk::UniformHeaveRow(geometry.panels[n], a, 0.0, omega_e);
  });
  const auto momentum = BoxKernel(h, a);
  const sk::HeadSeaShipModel kmodel(momentum, BoxMass(h), opt);
  const auto ref0 = sk::SolvePeriodicRaos(kmodel, w);
  const double lag_error = we.back() * geometry.dt_s;  // the largest ω_e Δt
  double peak03 = 0, peak05 = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    peak03 = std::max(peak03, std::abs(ref0.heave[i]));
    peak05 = std::max(peak05, std::abs(ref0.pitch[i]));
  }
  for (std::size_t i = 0; i < w.size(); ++i) {
    CHECK(std::abs(stf0.heave[i] - ref0.heave[i]) < lag_error * peak03);
    CHECK(std::abs(stf0.pitch[i] - ref0.pitch[i]) < lag_error * peak05);
  }
  // (2) b > 0: against the continuous equations with Z = a + b/(iω_e) (1% of the peak, as above: O(Δx/L)).
  const auto stf = sk::SolveStripTheoryRaos(model, w, [&](int n, double omega_e) {
    return sk::UniformHeaveRow(geometry.panels[n], a, b, omega_e);
  });
  std::vector<std::pair<cd, cd>> ref;
  double peak3 = 0, peak5 = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    ref.push_back(ContinuousRao(h, cd(a, -b / we[i]), cs, w[i]));
    peak3 = std::max(peak3, std::abs(ref.back().first));
    peak5 = std::max(peak5, std::abs(ref.back().second));
  }
  for (std::size_t i = 0; i < w.size(); ++i) {
    INFO("omega_e = " << we[i]);
    CHECK(std::abs(stf.heave[i] - ref[i].first) < 1e-2 * peak3);
    CHECK(std::abs(stf.pitch[i] - ref[i].second) < 1e-2 * peak5);
  }
}
