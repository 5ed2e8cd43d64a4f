// Cost of one evaluation of the default campaign (configs/optimize-catamaran.yaml at its start design: the
// 1000 t catamaran at 40 kn, 40 sections x 14 panels, two seas) with the objective averaged over headings
// (objective.headings_deg) against the head-sea objective:
//   /0  no headings: head seas by the time-domain strip method (the campaign's default objective)
//   /1  one heading, 150 deg, by the oblique-sea strip theory
//   /5  five headings 180, 165, 150, 135, 120 deg (equal weights), all by the oblique-sea strip theory
// The whole opt::Evaluator::Evaluate call of each (hull, RAOs, seas, resistance), one iteration per repetition:
//   build/bench/bench_campaign_headings --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
// Quote medians with the core count (docs/developer-guide.md). On the shared 2-core machine /1 takes minutes per
// repetition and /5 about five times that: run a single case with --benchmark_filter=.../1 when short of time.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "campaign/campaign_setup.h"
#include "campaign/run_campaign.h"

using namespace hullopt;

namespace {
const std::string kConfig = std::string(HULLOPT_SOURCE_DIR) + "/configs/optimize-catamaran.yaml";
// The start design of the default campaign (its base hull): L/B, B/T, Cp, LCF.
const std::vector<double> kStart = {11.0, 2.0, 0.69, -8.3};

campaign::LoadedCampaign Campaign(const std::vector<double>& headings) {
  YAML::Node config = YAML::LoadFile(kConfig);
  if (!headings.empty())
    for (double h : headings) config["optimize"]["objective"]["headings_deg"].push_back(h);
  return campaign::LoadCampaign(
      campaign::CampaignSpec::FromTree(io::CampaignCommand::kOptimize, config, kConfig));
}
}  // namespace

static void BM_EvaluationOverHeadings(benchmark::State& state) {
  const std::vector<double> headings = state.range(0) == 0   ? std::vector<double>{}
                                       : state.range(0) == 1 ? std::vector<double>{150.0}
                                                             : std::vector<double>{180.0, 165.0, 150.0, 135.0, 120.0};
  campaign::LoadedCampaign c = Campaign(headings);
  for (auto _ : state) {
    const opt::EvalResult r = c.evaluator->Evaluate(kStart);
    if (!r.produced) state.SkipWithError(r.error.c_str());
    benchmark::DoNotOptimize(r.objective);
  }
}
BENCHMARK(BM_EvaluationOverHeadings)->Arg(0)->Arg(1)->Arg(5)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

BENCHMARK_MAIN();
