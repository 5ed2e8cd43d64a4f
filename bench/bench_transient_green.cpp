// Cost of the transient Green function and of one strip carried through 40 steps with 14 panels.
//   ./build/bench/bench_transient_green --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "seakeeping/sections/section_shapes.h"
#include "seakeeping/strip/strip_kernel_builder.h"
#include "seakeeping/strip/strip_operators.h"
#include "seakeeping/green/transient_green.h"

using namespace hullopt::sk;

namespace {
// 64 (Y, Z, t) points spread over the regimes met in a strip: near and far, early and late, near z = 0.
struct Point {
  double Y, Z, t;
};
std::vector<Point> Points() {
  std::vector<Point> p;
  for (double Y : {0.0, 0.05, 0.4, -1.5})
    for (double Z : {-0.01, -0.1, -0.5, -2.0})
      for (double t : {0.05, 0.5, 2.0, 8.0}) p.push_back({Y, Z, t});
  return p;
}

void BM_TransientGreen(benchmark::State& state) {
  const auto pts = Points();
  double sink = 0;
  for (auto _ : state)
    for (const auto& q : pts) sink += TransientGreen(q.Y, q.Z, q.t, 9.81).h_z.real();
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations() *
                          pts.size());  // items/s = kernel evaluations (H, H_t, H') per s
}
BENCHMARK(BM_TransientGreen);

void BM_TransientGreenTimeIntegral(benchmark::State& state) {
  const auto pts = Points();
  TransientGreenTimeIntegral(0.1, -0.1, 1.0, 9.81);  // builds the Φ table once
  double sink = 0;
  for (auto _ : state)
    for (const auto& q : pts) sink += TransientGreenTimeIntegral(q.Y, q.Z, q.t, 9.81).real();
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations() * pts.size());
}
BENCHMARK(BM_TransientGreenTimeIntegral);

// A strip entered by a hull whose section grows from the bow (40 sections, 14 panels, dt = 0.02 s): all
// memory terms M_{n,k}, k < n, and the momentum rows, then the reduction to the strip kernel.
std::vector<std::vector<Panel>> Strip() {
  std::vector<std::vector<Panel>> panels;
  for (int n = 0; n < 40; ++n) {
    const double r = 0.2 + 0.8 * std::sin(0.5 * M_PI * std::min(1.0, (n + 1) / 20.0));
    panels.push_back(PanelSymmetricSection(SemicircleContour(r, 200), 14));
  }
  return panels;
}

void BM_StripOperators_40steps_14panels(benchmark::State& state) {
  const auto panels = Strip();
  for (auto _ : state) benchmark::DoNotOptimize(BuildStripOperators(panels, 0.02, 1025.0, 9.81));
}
BENCHMARK(BM_StripOperators_40steps_14panels)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_StripKernel_40steps_14panels(benchmark::State& state) {
  const auto panels = Strip();
  const auto ops = BuildStripOperators(panels, 0.02, 1025.0, 9.81);
  std::vector<double> x(40);
  for (int n = 0; n < 40; ++n) x[n] = 40.0 - n;
  for (auto _ : state) benchmark::DoNotOptimize(BuildStripKernel(ops, x));
}
BENCHMARK(BM_StripKernel_40steps_14panels)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
