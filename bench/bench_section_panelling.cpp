// Section panelling of one strip-station set (the geometry half of a strip kernel, StripKernelGeometry: every
// station's section interpolated, cut at the waterline and panelled by PanelSymmetricSection), 40 sections x
// 14 panels, one thread: the Delft 372 demihull from its offsets and the default campaign's start design (an
// NPL 5b-like parametric catamaran, both demihulls). Tracks the cost of the panelling against the kernel
// build (bench_rao's BM_KernelBuild/1). Run: build/bench/bench_section_panelling --benchmark_repetitions=10
// --benchmark_report_aggregates_only=true (quote the median with the core count).
#include <benchmark/benchmark.h>

#include <cmath>

#include "parametric_hull/hull_generator.h"
#include "seakeeping/strip/strip_geometry.h"
#include "tests/support/delft372_hull.h"

namespace sk = hullopt::sk;

namespace {

constexpr double kRho = 1000.0, kG = 9.81;

void BM_StationSetDelftDemihull(benchmark::State& state) {
  const hullopt::hull::HullForm hull = hullopt::testing::Delft372Hull(HULLOPT_SOURCE_DIR);
  sk::StripGeometryOptions o;  // 40 x 14
  o.body = 0;
  const double speed = 0.75 * std::sqrt(kG * 3.0);
  for (auto _ : state) benchmark::DoNotOptimize(sk::StripKernelGeometry(hull, o, speed, kRho, kG));
  state.counters["sections"] = o.sections;
}
BENCHMARK(BM_StationSetDelftDemihull)->Unit(benchmark::kMicrosecond)->UseRealTime();

void BM_StationSetCampaignCatamaran(benchmark::State& state) {
  hullopt::hull::DesignVariables dv;  // NPL 5b-like catamaran, round bilge (the default campaign's start)
  const hullopt::hull::HullForm hull = hullopt::hull::GenerateHull(dv);
  const sk::StripGeometryOptions o;  // 40 x 14, both demihulls
  for (auto _ : state) benchmark::DoNotOptimize(sk::StripKernelGeometry(hull, o, 20.0, 1025.0, kG));
  state.counters["sections"] = o.sections;
}
BENCHMARK(BM_StationSetCampaignCatamaran)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
