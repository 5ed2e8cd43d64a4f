// RAO sweep timing: 60 frequencies, 40 sections × 14 panels, one demihull (Delft 372 at
// Fn 0.75, the paper's transient Green-function kernel). Periodic path (2b) with 1 and 2 OpenMP threads, the
// time-marching path (2a) on the same sweep, and the kernel build (once per hull and speed) with 1 and 2
// threads, also with the strip steps at the cell faces (41 steps, StationLayout::kCellFaces) and with the
// paper's pressure form of the sectional force; one forced-oscillation run on the instantaneous hull. Run:
// build/bench/bench_rao (quote medians with the core count).
#include <benchmark/benchmark.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include <cmath>

#include "seakeeping/motions/calm_water.h"
#include "seakeeping/motions/forced_oscillation.h"
#include "seakeeping/motions/frequency_list.h"
#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/motions/periodic_motion_solver.h"
#include "seakeeping/motions/rao_solver.h"
#include "seakeeping/motions/strip_theory_stf.h"
#include "seakeeping/strip/strip_force_model.h"
#include "seakeeping/strip/strip_geometry.h"
#include "seakeeping/motions/time_marching_motion.h"
#include "tests/support/delft372_hull.h"

namespace sk = hullopt::sk;

namespace {

constexpr double kRho = 1000.0, kG = 9.81;

struct Demihull {
  hullopt::hull::HullForm hull = hullopt::testing::Delft372Hull(HULLOPT_SOURCE_DIR);
  double speed = 0.75 * std::sqrt(kG * 3.0);
  hullopt::hull::MassProperties mass = hullopt::testing::Delft372Mass();
  std::vector<double> omega;
  sk::StripKernel geometry, kernel, geometry_faces;
  Demihull() {
    mass.mass_kg *= 0.5;  // one demihull alone
    sk::StripGeometryOptions o;
    o.body = 0;
    geometry = sk::StripKernelGeometry(hull, o, speed, kRho, kG);
    kernel = geometry;
    o.layout = sk::StationLayout::kCellFaces;
    geometry_faces = sk::StripKernelGeometry(hull, o, speed, kRho, kG);
    sk::TransientGreenKernelBuilder()(&kernel);
    omega = sk::WaveFrequencies(sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kOmegaE, 3.0, 25.0, 60),
                                speed, kG, 3.0);
  }
};

const Demihull& TheDemihull() {
  static const Demihull d;
  return d;
}

sk::MotionOptions Options() {
  sk::MotionOptions o;
  o.damping_cs = 0.024;
  return o;
}

void SetThreads(int n) {
#ifdef _OPENMP
  omp_set_num_threads(n);
#endif
}

void BM_PeriodicSweep(benchmark::State& state) {
  const auto& d = TheDemihull();
  SetThreads(static_cast<int>(state.range(0)));
  const sk::HeadSeaShipModel model(d.kernel, d.mass, Options());
  for (auto _ : state) benchmark::DoNotOptimize(sk::SolvePeriodicRaos(model, d.omega));
  state.counters["frequencies"] = static_cast<double>(d.omega.size());
}
BENCHMARK(BM_PeriodicSweep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_TimeMarchingSweep(benchmark::State& state) {
  const auto& d = TheDemihull();
  const sk::HeadSeaShipModel model(d.kernel, d.mass, Options());
  sk::KernelStripForceModel forces(d.kernel);
  for (auto _ : state)
    benchmark::DoNotOptimize(sk::SolveMarchingRaos(model, forces, d.omega, sk::MarchingOptions{}));
}
BENCHMARK(BM_TimeMarchingSweep)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1)->Repetitions(3);

void BM_KernelBuild(benchmark::State& state) {
  const auto& d = TheDemihull();
  SetThreads(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    sk::StripKernel k = d.geometry;
    sk::TransientGreenKernelBuilder()(&k);
    benchmark::DoNotOptimize(k.force.data());
  }
}
BENCHMARK(BM_KernelBuild)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

void BM_KernelBuildCellFaces(benchmark::State& state) {
  const auto& d = TheDemihull();
  SetThreads(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    sk::StripKernel k = d.geometry_faces;
    sk::TransientGreenKernelBuilder()(&k);
    benchmark::DoNotOptimize(k.force.data());
  }
}
BENCHMARK(BM_KernelBuildCellFaces)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

// The reference paper's written sectional force (SectionalForce::kPressure): the transport rows of the moving
// contour beside the momentum rows (same table work), on the default cell-face steps.
void BM_KernelBuildPressureForm(benchmark::State& state) {
  const auto& d = TheDemihull();
  SetThreads(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    sk::StripKernel k = d.geometry_faces;
    sk::TransientGreenKernelBuilder(sk::SectionalForce::kPressure)(&k);
    benchmark::DoNotOptimize(k.force.data());
  }
}
BENCHMARK(BM_KernelBuildPressureForm)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

// One forced-heave run on the instantaneous hull (sk::SimulateForcedOscillation): both demihulls of Delft 372
// at Fn 0.75, 15 mm at ω_e 8.1 rad/s (ω √(L/g) 4.47, the heave resonance), 40 × 14, one ramp period and two
// analysed periods: one strip's operators per time step of the record.
void BM_ForcedOscillationRun(benchmark::State& state) {
  const auto& d = TheDemihull();
  SetThreads(static_cast<int>(state.range(0)));
  sk::ForcedOscillationOptions o;
  o.amplitude = 0.015;
  o.omega_e_rad_s = 8.1;
  o.damping_cs = 0.024;
  hullopt::hull::MassProperties mass = hullopt::testing::Delft372Mass();
  for (auto _ : state) {
    const auto r = sk::SimulateForcedOscillation(d.hull, mass, d.speed, kRho, kG, o);
    benchmark::DoNotOptimize(r.damping);
  }
}
BENCHMARK(BM_ForcedOscillationRun)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

// Calm water on the same hull at Fn 0.75, 40 × 14 (sk::SolveRunningAttitude): one strip march per attitude
// iteration (about 6), each with the strip's operators built once; one thread (one strip, nothing to share).
void BM_CalmWaterAttitude(benchmark::State& state) {
  const auto& d = TheDemihull();
  SetThreads(1);
  const hullopt::hull::MassProperties mass = hullopt::testing::Delft372Mass();
  for (auto _ : state) {
    const auto r = sk::SolveRunningAttitude(d.hull, mass, d.speed, kRho, kG, sk::CalmWaterOptions{});
    benchmark::DoNotOptimize(r.attitude);
    state.counters["iterations"] = r.iterations;
  }
}
BENCHMARK(BM_CalmWaterAttitude)->Unit(benchmark::kMillisecond)->UseRealTime();

// Conventional strip theory (method: strip_theory_stf) on the same demihull: 10 wavelengths, every (station,
// omega_e) section solved by the frequency-domain panel method (a fresh row cache per iteration).
void BM_StripTheorySweep(benchmark::State& state) {
  const auto& d = TheDemihull();
  SetThreads(static_cast<int>(state.range(0)));
  const sk::HeadSeaShipModel model(d.geometry, d.mass, Options());
  const std::vector<double> omega = sk::WaveFrequencies(
      sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kLambdaOverL, 0.8, 3.0, 10), d.speed, kG, 3.0);
  for (auto _ : state)
    benchmark::DoNotOptimize(sk::SolveStripTheoryRaos(model, omega, sk::FrequencyDomainSectionRows(d.geometry, 14)));
}
BENCHMARK(BM_StripTheorySweep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
