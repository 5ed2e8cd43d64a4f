// Generation plus hydrostatics of one hull (target: under 10 ms), for the four hull types.
#include <benchmark/benchmark.h>

#include "parametric_hull/hull_generator.h"
#include "parametric_hull/hydrostatics.h"

using namespace hullopt::hull;

namespace {
DesignVariables Design(HullType type) {
  DesignVariables dv;  // NPL 5b-like catamaran by default
  dv.type = type;
  if (type == HullType::kSwath) {  // SW1 of Table 1
    dv.section_style = SectionStyle::kSwathBulb;
    dv.L_over_B = 16.1;
    dv.B_over_T = 1.51;
    dv.Cb = 0.55;
    dv.Cp = 0.75;
    dv.Cwp = 0.38;
    dv.LCB_pct_L = -10.9;
    dv.LCF_pct_L = -14.6;
    dv.strut_ratio = 0.7;
    dv.transom_beam_ratio = 0.3;
    dv.transom_immersion = 0.6;
  } else if (type == HullType::kTrihull) {  // TRIa of Table 1
    dv.L_over_B = 8.0;
    dv.B_over_T = 5.35;
    dv.Cb = 0.38;
    dv.Cp = 0.80;
    dv.Cwp = 0.72;
    dv.LCB_pct_L = -11.8;
    dv.LCF_pct_L = -11.5;
    dv.transom_immersion = 0.4;
    dv.transom_beam_ratio = 0.3;
    dv.outrigger_L_over_B = 35;
  } else if (type == HullType::kMonohull) {  // S60 of Table 1
    dv.L_over_B = 8.0;
    dv.B_over_T = 4.01;
    dv.Cp = 0.59;
    dv.Cwp = 0.84;
    dv.LCB_pct_L = -5.4;
    dv.LCF_pct_L = -6.3;
  }
  return dv;
}

void BM_GenerateAndHydrostatics(benchmark::State& state) {
  const DesignVariables dv = Design(static_cast<HullType>(state.range(0)));
  for (auto _ : state) {
    const HullForm h = GenerateHull(dv);
    benchmark::DoNotOptimize(ComputeHydrostatics(h, dv.rho_kg_m3));
  }
  state.SetLabel(ToString(dv.type));
}
}  // namespace

BENCHMARK(BM_GenerateAndHydrostatics)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
