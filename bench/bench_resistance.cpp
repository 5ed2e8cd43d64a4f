// Calm-water resistance of the default campaign's catamaran (1000 t NPL-5b-like, 41 stations) at its design
// speed 40 kn: what resistance adds to one campaign evaluation (target: under 10 ms). "Model" builds the
// centre-plane grids, wetted surfaces and transom (once per design); "AtSpeed" is the Michell integral and
// friction at one speed; "Design" both, i.e. the cost per campaign evaluation. Also at 20 kn (Fn 0.4), where
// the λ integrand oscillates more and costs more.
#include <benchmark/benchmark.h>

#include "parametric_hull/hull_generator.h"
#include "resistance/calm_water_resistance.h"

using namespace hullopt;

namespace {
hull::HullForm DefaultCatamaran() {
  hull::DesignVariables dv;  // NPL 5b-like catamaran, 1000 t, spacing 0.25 L
  return hull::GenerateHull(dv);
}
constexpr double kKnot = 1852.0 / 3600.0;

void BM_ResistanceModel(benchmark::State& s) {
  const hull::HullForm h = DefaultCatamaran();
  for (auto _ : s) benchmark::DoNotOptimize(res::CalmWaterResistance(h, res::ResistanceOptions{}));
}
void BM_ResistanceAtSpeed(benchmark::State& s) {
  const hull::HullForm h = DefaultCatamaran();
  const res::CalmWaterResistance m(h, res::ResistanceOptions{});
  for (auto _ : s) benchmark::DoNotOptimize(m.At(s.range(0) * kKnot, 1025.0, 9.81));
}
void BM_ResistanceDesign(benchmark::State& s) {
  const hull::HullForm h = DefaultCatamaran();
  for (auto _ : s) {
    const res::CalmWaterResistance m(h, res::ResistanceOptions{});
    benchmark::DoNotOptimize(m.At(40.0 * kKnot, 1025.0, 9.81));
  }
}
}  // namespace

BENCHMARK(BM_ResistanceModel)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ResistanceAtSpeed)->Arg(40)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ResistanceDesign)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
