// RAO sweep timing (issue 4, item 5): 60 frequencies, 40 sections × 14 panels, one demihull.
// Periodic path (2b) with 1 and 2 OpenMP threads, and the time-marching path (2a) on the same sweep.
//
// Until the transient-Green-function kernel is wired in, the kernel is a hand-built one of the production
// size and shape (every force[n][m] row dense, 14 panels per step), so the solver cost is measured exactly;
// the kernel build is timed separately once BuildStripKernel is available.
#include <benchmark/benchmark.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include <cmath>

#include "seakeeping/frequency_list.h"
#include "seakeeping/head_sea_ship_model.h"
#include "seakeeping/impulsive_strip_kernel.h"
#include "seakeeping/periodic_motion_solver.h"
#include "seakeeping/strip_force_model.h"
#include "seakeeping/strip_geometry.h"
#include "seakeeping/time_marching_motion.h"
#include "tests/support/box_strip_kernel.h"
#include "tests/support/delft372_hull.h"

namespace sk = hullopt::sk;

namespace {

struct Sweep {
  hullopt::testing::BoxHull hull;
  sk::StripKernel kernel;
  hullopt::hull::MassProperties mass;
  std::vector<double> omega;
  Sweep() {
    hull.sections = 40;
    hull.bottom_panels = 12;  // 1 + 12 + 1 = 14 panels per section
    kernel = hullopt::testing::BoxKernel(hull, 400.0);
    // Dense memory tail, decaying and oscillating like a free-surface memory kernel, small enough to stay
    // stable.
    for (int n = 0; n < kernel.Steps(); ++n)
      for (int m = 0; m + 1 < n; ++m)
        kernel.force[n][m] =
            kernel.force[n][n] * (-0.02 * std::exp(-(n - m) / 8.0) * std::cos(0.4 * (n - m)));
    mass = {hull.rho * hull.L * hull.B * hull.T, hull.L / 2, hull.L / 4, 0.0};
    omega = sk::WaveFrequencies(sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kOmegaE, 1.0, 9.0, 60),
                                hull.speed, hull.g, hull.L);
  }
};

const Sweep& TheSweep() {
  static const Sweep s;
  return s;
}

void BM_PeriodicSweep(benchmark::State& state) {
#ifdef _OPENMP
  omp_set_num_threads(static_cast<int>(state.range(0)));
#endif
  const auto& s = TheSweep();
  sk::MotionOptions o;
  o.damping_cs = 0.05;
  const sk::HeadSeaShipModel model(s.kernel, s.mass, o);
  for (auto _ : state) benchmark::DoNotOptimize(sk::SolvePeriodicRaos(model, s.omega));
  state.counters["frequencies"] = static_cast<double>(s.omega.size());
}
BENCHMARK(BM_PeriodicSweep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_TimeMarchingSweep(benchmark::State& state) {
  const auto& s = TheSweep();
  sk::MotionOptions o;
  o.damping_cs = 0.05;
  const sk::HeadSeaShipModel model(s.kernel, s.mass, o);
  sk::KernelStripForceModel forces(s.kernel);
  sk::MarchingOptions mo;
  for (auto _ : state) benchmark::DoNotOptimize(sk::SolveMarchingRaos(model, forces, s.omega, mo));
}
BENCHMARK(BM_TimeMarchingSweep)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1)->Repetitions(3);

// End to end on a real demihull (Delft 372, one demihull alone, 40 × 14): geometry, kernel (impulsive
// stand-in until the transient-Green-function kernel is wired in) and the 60-frequency periodic sweep.
void BM_Delft372DemihullSweep(benchmark::State& state) {
#ifdef _OPENMP
  omp_set_num_threads(static_cast<int>(state.range(0)));
#endif
  const auto hull = hullopt::testing::Delft372Hull(HULLOPT_SOURCE_DIR);
  const double U = 0.75 * std::sqrt(9.81 * 3.0);
  const auto omega = sk::WaveFrequencies(
      sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kOmegaE, 3.0, 25.0, 60), U, 9.81, 3.0);
  hullopt::hull::MassProperties mass = hullopt::testing::Delft372Mass();
  mass.mass_kg *= 0.5;
  sk::StripGeometryOptions o;
  o.body = 0;
  sk::MotionOptions mo;
  mo.damping_cs = 0.024;
  for (auto _ : state) {
    auto k = sk::StripKernelGeometry(hull, o, U, 1000.0, 9.81);
    sk::FillImpulsiveStripKernel(&k);
    const sk::HeadSeaShipModel model(k, mass, mo);
    benchmark::DoNotOptimize(sk::SolvePeriodicRaos(model, omega));
  }
}
BENCHMARK(BM_Delft372DemihullSweep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
