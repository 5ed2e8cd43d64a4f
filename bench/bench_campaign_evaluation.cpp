// Where one evaluation of the default campaign (configs/optimize-catamaran.yaml at its start design) spends its
// time: the whole opt::Evaluator::Evaluate call, and the physics phases it is made of, each timed alone on the
// same design: hull generation, hydrostatics, the strip kernel, the periodic RAO solve, seas + MSI and the
// calm-water resistance. What the whole costs beyond the sum of the phases is the machinery around the physics
// (setting up the trial design, copies, checks, messages). BM_TrialDesignSetup times that set-up on its own.
//   build/bench/bench_campaign_evaluation --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// BM_DesignRaosAndMsi/0 and /1: the RAOs and MSI of the start design on the fixed and on the adaptive grid.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "campaign/campaign_setup.h"
#include "campaign/run_campaign.h"
#include "io/config/design_config.h"
#include "io/config/motion_config.h"
#include "evaluation/trial_design.h"
#include "io/config/seas_config.h"
#include "parametric_hull/hull_generator.h"
#include "resistance/calm_water_resistance.h"
#include "seakeeping/motions/periodic_motion_solver.h"
#include "seas/design_evaluation.h"

using namespace hullopt;

namespace {
const std::string kConfig = std::string(HULLOPT_SOURCE_DIR) + "/configs/optimize-catamaran.yaml";
// The start design of the default campaign (its base hull): L/B, B/T, Cp, LCF.
const std::vector<double> kStart = {11.0, 2.0, 0.69, -8.3};

campaign::LoadedCampaign& Campaign() {
  static campaign::LoadedCampaign c =
      campaign::LoadCampaign(campaign::CampaignSpec::FromFile(io::CampaignCommand::kOptimize, kConfig));
  return c;
}

// The base design with the campaign's mass rule (displacement fixed, LCG = LCB, k_yy = 0.25 L, KG = T).
const eval::DesignCase& Design() {
  static const eval::DesignCase d = [] {
    io::YamlMap root = io::YamlMap::LoadFile(kConfig);
    eval::DesignCase c = io::LoadDesignCase(root, kConfig, "design");
    c.mass.mass_kg = c.hydrostatics.displacement_kg;
    c.mass.lcg_m_from_ap = c.hydrostatics.lcb_m_from_ap;
    c.mass.kyy_m = 0.25 * c.hydrostatics.L_m;
    c.mass.kg_m = c.hydrostatics.T_m;
    return c;
  }();
  return d;
}

hull::DesignVariables Variables() {
  io::YamlMap root = io::YamlMap::LoadFile(kConfig);
  return io::ParseHullConfig(root, io::ParseWater(root)).design;
}

sk::RaoSolverOptions Options() { return eval::RaoOptions(Design().solver, "design", Design().solver.cs()); }
}  // namespace

static void BM_Evaluation(benchmark::State& state) {
  opt::Evaluator& ev = *Campaign().evaluator;
  for (auto _ : state) benchmark::DoNotOptimize(ev.Evaluate(kStart));
}
BENCHMARK(BM_Evaluation)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_HullGeneration(benchmark::State& state) {
  const hull::DesignVariables v = Variables();
  for (auto _ : state) benchmark::DoNotOptimize(hull::GenerateHull(v));
}
BENCHMARK(BM_HullGeneration)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_Hydrostatics(benchmark::State& state) {  // an evaluation computes them twice (at rest, with KG)
  const eval::DesignCase& d = Design();
  for (auto _ : state) {
    benchmark::DoNotOptimize(hull::ComputeHydrostatics(d.hull, d.water.rho_kg_m3));
    benchmark::DoNotOptimize(hull::ComputeHydrostatics(d.hull, d.water.rho_kg_m3, d.mass.kg_m));
  }
}
BENCHMARK(BM_Hydrostatics)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_StripKernel(benchmark::State& state) {
  const eval::DesignCase& d = Design();
  const sk::RaoSolverOptions o = Options();
  for (auto _ : state)
    benchmark::DoNotOptimize(sk::BuildHullStripKernel(d.running_hull, o, d.speed_m_s, d.water.rho_kg_m3,
                                                      d.water.g_m_s2, sk::TransientGreenKernelBuilder()));
}
BENCHMARK(BM_StripKernel)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_PeriodicRaos(benchmark::State& state) {
  const eval::DesignCase& d = Design();
  const sk::RaoSolverOptions o = Options();
  const sk::StripKernel kernel = sk::BuildHullStripKernel(d.running_hull, o, d.speed_m_s, d.water.rho_kg_m3,
                                                          d.water.g_m_s2, sk::TransientGreenKernelBuilder());
  const std::vector<double> w = eval::SeaFrequencies(d);
  for (auto _ : state) {
    const sk::HeadSeaShipModel model(kernel, d.mass, o.motion);
    benchmark::DoNotOptimize(sk::SolvePeriodicRaos(model, w));
  }
}
BENCHMARK(BM_PeriodicRaos)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_SeasAndMsi(benchmark::State& state) {
  const eval::DesignCase& d = Design();
  const sk::RaoTable rao = eval::ComputeDesignRaos(d, eval::SeaFrequencies(d));
  io::YamlMap root = io::YamlMap::LoadFile(kConfig);
  const auto spectra = sk::BuildSpectra(io::ReadSeas(root));
  for (auto _ : state) benchmark::DoNotOptimize(sk::EvaluateDesign(rao, d.Extent(), spectra, {}, {}));
}
BENCHMARK(BM_SeasAndMsi)->Unit(benchmark::kMillisecond)->UseRealTime();

// One design's RAOs and MSI in the campaign's seas: the strip kernel, the sweep and the seas, on the fixed
// default grid (/0, solver.adaptive_grid: off) and refined until the peaks and the MSI converge (/1, the default).
static void BM_DesignRaosAndMsi(benchmark::State& state) {
  eval::DesignCase d = Design();
  d.solver.grid.enabled = state.range(0) != 0;
  io::YamlMap root = io::YamlMap::LoadFile(kConfig);
  const eval::GridSeas seas{sk::BuildSpectra(io::ReadSeas(root)), d.Extent(), {}, {}};
  std::size_t count = 0;
  for (auto _ : state) {
    const sk::RaoTable rao = eval::ComputeDesignRaos(d, eval::SeaFrequencies(d), -1.0, &seas);
    benchmark::DoNotOptimize(sk::EvaluateDesign(rao, d.Extent(), seas.spectra, {}, {}));
    count = rao.omega_rad_s.size();
  }
  state.counters["frequencies"] = static_cast<double>(count);
}
BENCHMARK(BM_DesignRaosAndMsi)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_CalmWaterResistance(benchmark::State& state) {
  const eval::DesignCase& d = Design();
  for (auto _ : state)
    benchmark::DoNotOptimize(res::CalmWaterResistance(d.hull, {}).At(d.speed_m_s, d.water.rho_kg_m3, d.water.g_m_s2));
}
BENCHMARK(BM_CalmWaterResistance)->Unit(benchmark::kMillisecond)->UseRealTime();

// The trial design as the evaluator sets it up from x (hull generation and hydrostatics included).
static void BM_TrialDesignSetup(benchmark::State& state) {
  io::YamlMap root = io::YamlMap::LoadFile(kConfig);
  io::DesignConfig c;
  io::LoadDesignCase(root, kConfig, "design", true, &c);
  const eval::DesignBasis basis = io::TrialBasis(c, kConfig);
  const auto fields = eval::TrialFields({"L_over_B", "B_over_T", "Cp", "LCF_pct_L"});
  for (auto _ : state) benchmark::DoNotOptimize(eval::BuildTrialDesign(basis, fields, kStart));
}
BENCHMARK(BM_TrialDesignSetup)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
