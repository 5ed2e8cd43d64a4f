// Overhead of the campaign machinery per evaluation, measured on a free analytic objective (sphere, 4
// variables): the NLopt driver (algorithm + constraint bookkeeping + record sink), logging a history row with
// fsync (what makes a campaign resumable), replaying a logged evaluation, and ordered parallel evaluation.
// The real MSI objective costs orders of magnitude more per evaluation; these figures bound what the
// machinery adds to it.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>

#include "io/formats/history_csv.h"
#include "optimizer/analytic_objectives.h"
#include "optimizer/design_sampling.h"
#include "optimizer/nlopt_driver.h"
#include "optimizer/parallel_evaluation.h"

using namespace hullopt;

namespace {
opt::CampaignDefinition Campaign(const std::string& algorithm, int max_eval) {
  opt::CampaignDefinition c;
  c.algorithm = algorithm;
  for (int i = 0; i < 4; ++i) c.variables.push_back({"x" + std::to_string(i + 1), -2, 2, -1});
  c.constraints = {{"sum_max", "sum", opt::Constraint::Kind::kMax, 1.0}};
  c.stopping.max_evaluations = max_eval;
  c.stopping.xtol_rel = 0;  // run exactly max_eval evaluations
  c.stopping.ftol_rel = 0;
  return c;
}
opt::AnalyticObjectiveOptions Sphere() {
  opt::AnalyticObjectiveOptions o;
  o.function = "sphere";
  o.dimension = 4;
  return o;
}
// A typical MSI campaign row: 4 variables, 2 seas, 1 constrained quantity.
io::HistoryLayout RowLayout() { return {{"x1", "x2", "x3", "x4"}, {"msi_sea1_pct", "msi_sea2_pct"}, {"L_m"}}; }
opt::EvaluationRecord RowRecord() {
  opt::EvaluationRecord rec;
  rec.x = {0.1, 0.2, 0.3, 0.4};
  rec.result.objective = 1.0 / 3.0;
  rec.result.sea_values = {2.0 / 3.0, 5.0 / 7.0};
  rec.feasible = true;
  return rec;
}
}  // namespace

// Driver overhead per evaluation (NLopt algorithm work included), no I/O.
static void BM_NloptDriverPerEvaluation(benchmark::State& state, const char* algorithm) {
  opt::AnalyticEvaluator ev(Sphere());
  const auto c = Campaign(algorithm, 500);
  long evals = 0;
  for (auto _ : state) {
    opt::NloptDriver d(c, ev);
    const auto r =
        d.Run(0, nullptr, [&](const opt::EvaluationRecord& rec) { benchmark::DoNotOptimize(rec); });
    evals += r.evaluations;
  }
  state.SetItemsProcessed(evals);
}
BENCHMARK_CAPTURE(BM_NloptDriverPerEvaluation, LN_COBYLA, "LN_COBYLA")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_NloptDriverPerEvaluation, LN_BOBYQA_AUGLAG, "LN_BOBYQA")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_NloptDriverPerEvaluation, GN_ISRES, "GN_ISRES")->Unit(benchmark::kMillisecond);

// Formatting one history row (%.17g) and appending it with fsync: the price of resumability per evaluation.
static void BM_HistoryAppendWithFsync(benchmark::State& state) {
  const io::HistoryLayout layout = RowLayout();
  const opt::EvaluationRecord rec = RowRecord();
  const std::string path = "/tmp/hullopt_bench_history.csv";
  io::HistoryAppender w(path, layout, 0);
  long n = 0;
  for (auto _ : state) w.Append(io::FormatHistoryRow(n++, rec, {75.0}, layout));
  state.SetItemsProcessed(n);
  std::remove(path.c_str());
}
BENCHMARK(BM_HistoryAppendWithFsync)->Unit(benchmark::kMicrosecond);

// Replaying a logged run (resume): the driver with every evaluation taken from the log.
static void BM_ReplayPerEvaluation(benchmark::State& state) {
  opt::AnalyticEvaluator ev(Sphere());
  const auto c = Campaign("LN_COBYLA", 500);
  std::vector<opt::EvaluationRecord> log;
  {
    opt::NloptDriver d(c, ev);
    d.Run(0, nullptr, [&](const opt::EvaluationRecord& rec) { log.push_back(rec); });
  }
  const opt::ReplayLookup lookup = [&](int, int step) -> const opt::EvaluationRecord* {
    return step < static_cast<int>(log.size()) ? &log[step] : nullptr;
  };
  long evals = 0;
  for (auto _ : state) {
    opt::NloptDriver d(c, ev);
    evals += d.Run(0, lookup, nullptr).evaluations;
  }
  state.SetItemsProcessed(evals);
}
BENCHMARK(BM_ReplayPerEvaluation)->Unit(benchmark::kMillisecond);

// Reading a 1000-row log back on resume (parsing and checking each row), per row.
static void BM_ReadHistoryPerRow(benchmark::State& state) {
  const io::HistoryLayout layout = RowLayout();
  const opt::EvaluationRecord rec = RowRecord();
  std::string text = layout.Header() + "\n";
  for (long i = 0; i < 1000; ++i) text += io::FormatHistoryRow(i, rec, {75.0}, layout);
  long rows = 0;
  for (auto _ : state) {
    const io::HistoryFile f = io::ParseHistory(text, "bench.csv", layout);
    rows += static_cast<long>(f.rows.size());
  }
  state.SetItemsProcessed(rows);
}
BENCHMARK(BM_ReadHistoryPerRow)->Unit(benchmark::kMillisecond);

// Ordered parallel evaluation of 200 Sobol samples of a 2 ms objective: threads = 1, 2.
static void BM_ExploreOrdered2msObjective(benchmark::State& state) {
  auto o = Sphere();
  o.eval_delay_ms = 2.0;
  opt::AnalyticEvaluator ev(o);
  const auto c = Campaign("LN_COBYLA", 1);
  const auto xs = opt::SampleDesigns(c, "sobol", 200);
  long n = 0;
  for (auto _ : state) {
    opt::EvaluateInOrder(
        ev, xs, 0, static_cast<int>(xs.size()), static_cast<int>(state.range(0)),
        [](int i, const std::vector<double>& x, const opt::EvalResult& r, double wall) {
          opt::EvaluationRecord rec;
          rec.step = i;
          rec.x = x;
          rec.result = r;
          rec.wall_time_s = wall;
          return rec;
        },
        [&](const opt::EvaluationRecord&) { ++n; });
  }
  state.SetItemsProcessed(n);
}
BENCHMARK(BM_ExploreOrdered2msObjective)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
