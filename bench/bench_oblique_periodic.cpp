// Cost per heading of the time-domain strip method in oblique seas (sk::SolveObliquePeriodic): one Delft 372
// demihull on the centreline, 40 sections x 14 panels on the cell faces, Fn 0.75, Cs 0.024, 20 wave
// frequencies (λ/L 0.8–3), 1 and 5 headings spread over 180° to 90°, on a strip kernel with the lateral rows
// built once outside the timing. For reference: the head-sea periodic path (sk::SolvePeriodicRaos, heave and
// pitch) on the same kernel, and the kernel builds themselves (full sections with lateral rows; the head-sea
// path's mirror-reduced kernel). Quote medians with the core count (docs/developer-guide.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "seakeeping/motions/frequency_list.h"
#include "seakeeping/motions/oblique_periodic_solver.h"
#include "seakeeping/motions/periodic_motion_solver.h"
#include "seakeeping/motions/rao_solver.h"
#include "tests/support/delft372_hull.h"

namespace sk = hullopt::sk;

namespace {

constexpr double kRho = 1000.0, kG = 9.81, kL = 3.0;

double Speed() { return 0.75 * std::sqrt(kG * kL); }

hullopt::hull::HullForm Demihull() {
  hullopt::hull::HullForm h = hullopt::testing::Delft372Hull(HULLOPT_SOURCE_DIR);
  h.type = "monohull";
  h.bodies.resize(1);
  h.bodies[0].y_centre_m = 0.0;
  return h;
}

struct Case {
  hullopt::hull::HullForm hull = Demihull();
  hullopt::hull::MassProperties mass = hullopt::testing::Delft372Mass();
  sk::RaoSolverOptions options =
      hullopt::testing::Delft372SolverOptions(sk::RaoSolverOptions::Method::kTimeDomainStrip);
  sk::StripKernel kernel;
  std::unique_ptr<sk::HeadSeaShipModel> model;
  sk::ObliquePeriodicOptions oblique;
  std::vector<double> omega;
  Case() {
    mass.mass_kg *= 0.5;  // one demihull of the catamaran's mass
    kernel =
        sk::BuildHullStripKernel(hull, options, Speed(), kRho, kG, sk::TransientGreenLateralKernelBuilder());
    model = std::make_unique<sk::HeadSeaShipModel>(kernel, mass, options.motion);
    oblique.mass.mass_kg = mass.mass_kg;
    oblique.mass.x_g_m = mass.lcg_m_from_ap;
    oblique.mass.z_g_m = mass.kg_m - hull.draught_m;
    oblique.mass.inertia_kg_m2.diagonal() << mass.mass_kg * 0.08 * 0.08,
        mass.mass_kg * mass.kyy_m * mass.kyy_m, mass.mass_kg * mass.kyy_m * mass.kyy_m;
    omega = sk::WaveFrequencies(
        sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kLambdaOverL, 0.8, 3.0, 20), Speed(), kG, kL);
  }
};

const Case& TheCase() {
  static const Case c;
  return c;
}

// state.range(0): number of headings.
void BM_ObliquePeriodicHeadings(benchmark::State& state) {
  const Case& c = TheCase();
  const int nh = static_cast<int>(state.range(0));
  std::vector<double> headings;
  for (int h = 0; h < nh; ++h) headings.push_back(nh == 1 ? 180.0 : 180.0 - 90.0 * h / (nh - 1));
  for (auto _ : state) {
    const auto r = sk::SolveObliquePeriodic(*c.model, c.omega, headings, c.oblique);
    benchmark::DoNotOptimize(r.waves.data());
  }
  state.counters["headings"] = nh;
  state.counters["per_heading_s"] =
      benchmark::Counter(nh, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ObliquePeriodicHeadings)
    ->Arg(1)
    ->Arg(5)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

void BM_HeadSeaPeriodic(benchmark::State& state) {
  const Case& c = TheCase();
  for (auto _ : state) {
    const auto t = sk::SolvePeriodicRaos(*c.model, c.omega);
    benchmark::DoNotOptimize(t.heave.data());
  }
}
BENCHMARK(BM_HeadSeaPeriodic)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

// state.range(0): 1 the full-section kernel with lateral rows, 0 the head-sea path's mirror-reduced kernel.
void BM_KernelBuild(benchmark::State& state) {
  const Case& c = TheCase();
  const auto builder =
      state.range(0) ? sk::TransientGreenLateralKernelBuilder() : sk::TransientGreenKernelBuilder();
  for (auto _ : state) {
    const auto k = sk::BuildHullStripKernel(c.hull, c.options, Speed(), kRho, kG, builder);
    benchmark::DoNotOptimize(k.force.data());
  }
}
BENCHMARK(BM_KernelBuild)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
