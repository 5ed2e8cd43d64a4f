// Ship motions on a real hull (Delft 372 catamaran, both demihulls in the strips, Fn 0.75, Cs 0.024): the two
// solution paths agree and the static (long-wave) limit holds.
//
// Kernel: the impulsive (φ = 0) strip kernel until the transient-Green-function kernel is wired in; the
// checks here concern the ship equations and the two paths over the same strips, which hold for any kernel.
#include <catch2/catch.hpp>
#include <cmath>

#include "seakeeping/motions/frequency_list.h"
#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/strip/impulsive_strip_kernel.h"
#include "seakeeping/motions/periodic_motion_solver.h"
#include "seakeeping/strip/strip_force_model.h"
#include "seakeeping/strip/strip_geometry.h"
#include "seakeeping/motions/time_marching_motion.h"
#include "support/delft372_hull.h"

namespace sk = hullopt::sk;

namespace {
constexpr double kG = 9.81, kRho = 1000.0;  // fresh-water tank
const double kSpeed = 0.75 * std::sqrt(kG * 3.0);

sk::StripKernel Delft372Kernel(int sections, int panels) {
  sk::StripGeometryOptions o;
  o.sections = sections;
  o.panels = panels;
  auto k = sk::StripKernelGeometry(hullopt::testing::Delft372Hull(HULLOPT_SOURCE_DIR), o, kSpeed, kRho, kG);
  sk::FillImpulsiveStripKernel(&k);
  return k;
}
}  // namespace

TEST_CASE("Delft 372: time marching agrees with the periodic steady state", "[motions][delft372][marching]") {
  const auto kernel = Delft372Kernel(40, 14);
  sk::MotionOptions mo;
  mo.damping_cs = 0.024;
  mo.hull_name = "delft372";
  const sk::HeadSeaShipModel model(kernel, hullopt::testing::Delft372Mass(), mo);
  // Heave peak from a fine periodic sweep, then 0.3 to 3 times it.
  const auto fine = sk::SolvePeriodicRaos(
      model, sk::WaveFrequencies(sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kOmegaE, 3, 20, 171),
                                 kSpeed, kG, 3.0));
  double peak_we = 0, peak = 0;
  for (std::size_t i = 0; i < fine.heave.size(); ++i)
    if (std::abs(fine.heave[i]) > peak) peak = std::abs(fine.heave[i]), peak_we = fine.omega_e_rad_s[i];
  const auto w = sk::WaveFrequencies(
      sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kOmegaE, 0.3 * peak_we, 3.0 * peak_we, 13),
      kSpeed, kG, 3.0);
  // Against the exact steady state of the marching scheme (trapezoid kinematics, docs/ship-motions.md), as in
  // test_ship_motions_transient_kernel.cpp: the continuous-time kinematics differ from marching by the
  // trapezoid frequency warp (ω_e Δt)²/12, which on this stand-in kernel's sharp resonance reaches 1.4% of
  // the pitch peak with cell-face stations and is not a disagreement between the paths.
  const auto periodic = sk::SolvePeriodicRaos(model, w, sk::PeriodicKinematics::kTrapezoid);
  sk::KernelStripForceModel forces(kernel);
  const auto marched = sk::SolveMarchingRaos(model, forces, w, sk::MarchingOptions{});
  double peak3 = 0, peak5 = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    peak3 = std::max(peak3, std::abs(periodic.heave[i]));
    peak5 = std::max(peak5, std::abs(periodic.pitch[i]));
  }
  // Path agreement: magnitudes within 1% of the curve's peak, phases within 3° (where the response is
  // more than 1% of its peak: below that the phase of a vanishing response is not meaningful).
  constexpr double kAmpTol = 0.01, kPhaseTolDeg = 3.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    INFO("omega_e = " << periodic.omega_e_rad_s[i] << " periodic " << periodic.heave[i] << " "
                      << periodic.pitch[i] << " marched " << marched.heave[i] << " " << marched.pitch[i]);
    CHECK(std::abs(std::abs(marched.heave[i]) - std::abs(periodic.heave[i])) < kAmpTol * peak3);
    CHECK(std::abs(std::abs(marched.pitch[i]) - std::abs(periodic.pitch[i])) < kAmpTol * peak5);
    if (std::abs(periodic.heave[i]) > 0.01 * peak3)
      CHECK(std::abs(std::arg(marched.heave[i] / periodic.heave[i])) * 180 / M_PI < kPhaseTolDeg);
    if (std::abs(periodic.pitch[i]) > 0.01 * peak5)
      CHECK(std::abs(std::arg(marched.pitch[i] / periodic.pitch[i])) * 180 / M_PI < kPhaseTolDeg);
  }
}

TEST_CASE("Delft 372: heave and pitch RAOs tend to 1 in long waves", "[motions][delft372][limits]") {
  const auto kernel = Delft372Kernel(40, 14);
  sk::MotionOptions mo;
  mo.damping_cs = 0.024;
  const sk::HeadSeaShipModel model(kernel, hullopt::testing::Delft372Mass(), mo);
  const auto r = sk::SolvePeriodicRaos(model, {0.05});  // λ = 24.7 km, λ/L ≈ 8000
  constexpr double kLimitTol = 0.02;                    // long-wave limit: 2%
  CHECK(std::abs(std::abs(r.heave[0]) - 1.0) < kLimitTol);
  CHECK(std::abs(std::abs(r.pitch[0]) - 1.0) < kLimitTol);
}

#ifdef _OPENMP
#include <omp.h>
TEST_CASE("Delft 372: identical results with 1 and 2 threads", "[motions][delft372][threads]") {
  const int saved = omp_get_max_threads();
  std::vector<sk::RaoTable> r;
  std::vector<sk::StripKernel> k;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    k.push_back(Delft372Kernel(20, 8));
    sk::MotionOptions mo;
    mo.damping_cs = 0.024;
    const sk::HeadSeaShipModel model(k.back(), hullopt::testing::Delft372Mass(), mo);
    r.push_back(sk::SolvePeriodicRaos(model, {2.0, 3.0, 4.0, 5.0}));
  }
  omp_set_num_threads(saved);
  for (int n = 0; n < k[0].Steps(); ++n)
    for (int m = 0; m <= n; ++m) CHECK(k[0].force[n][m] == k[1].force[n][m]);  // bitwise
  for (std::size_t i = 0; i < r[0].heave.size(); ++i) {
    CHECK(r[0].heave[i] == r[1].heave[i]);
    CHECK(r[0].pitch[i] == r[1].pitch[i]);
  }
}
#endif
