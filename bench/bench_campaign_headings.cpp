// Cost of one evaluation of the default campaign (configs/optimize-catamaran.yaml at its start design: the
// 1000 t catamaran at 40 kn, 40 sections x 14 panels, two seas) with the objective averaged over headings
// (objective.headings_deg) against the head-sea objective. Arguments (headings, method):
//   /0/0  no headings: head seas by the time-domain strip method (the campaign's default objective)
//   /1/0  one heading, 150 deg, by the time-domain strip method in oblique seas (the default method)
//   /5/0  five headings 180, 165, 150, 135, 120 deg (equal weights), by the same
//   /1/1, /5/1  the same by the oblique-sea strip theory (solver.method: strip_theory_stf)
// The whole opt::Evaluator::Evaluate call of each (hull, RAOs, seas, resistance), one iteration per repetition:
//   build/bench/bench_campaign_headings --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
// Quote medians with the core count (docs/developer-guide.md). The strip-theory cases take about a minute (/1/1)
// and four minutes (/5/1) per repetition on the 2-core machine: --benchmark_filter='/[015]/0/' leaves them out.
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

campaign::LoadedCampaign Campaign(const std::vector<double>& headings, bool strip_theory) {
  YAML::Node config = YAML::LoadFile(kConfig);
  if (strip_theory) config["solver"]["method"] = "strip_theory_stf";
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
  campaign::LoadedCampaign c = Campaign(headings, state.range(1) == 1);
  for (auto _ : state) {
    const opt::EvalResult r = c.evaluator->Evaluate(kStart);
    if (!r.produced) state.SkipWithError(r.error.c_str());
    benchmark::DoNotOptimize(r.objective);
  }
}
BENCHMARK(BM_EvaluationOverHeadings)
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({5, 0})
    ->Args({1, 1})
    ->Args({5, 1})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_MAIN();
