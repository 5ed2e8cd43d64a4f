// hullopt explore CONFIG --out DIR: evaluate a Sobol or Latin-hypercube sample of the design box in parallel
// (OpenMP threads, MPI ranks), log samples.csv in sample order (identical for any thread/rank count),
// and estimate the sensitivity of the objective to each variable. Resumable like optimize.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "app/campaign_journal.h"
#include "app/campaign_setup.h"
#include "app/campaign_report.h"
#include "app/commands.h"
#include "app/mpi_context.h"
#include "app/output_dir.h"
#include "app/progress.h"
#include "app/run_checks.h"
#include "hullopt/version.h"
#include "io/campaign_outputs.h"
#include "io/campaign_plots.h"
#include "io/input_error.h"
#include "optimizer/design_sampling.h"
#include "optimizer/parallel_evaluation.h"
#include "optimizer/sensitivity.h"

namespace hullopt::app {
namespace {

struct ExploreCliOptions {
  std::string config;
  std::string out;
  int threads = 0;
  int chunk = 0;
  bool quiet = false;
};

void RunExplore(const ExploreCliOptions& o) {
  const auto wall0 = std::chrono::steady_clock::now();
  LoadedCampaign lc = LoadCampaign(o.config, io::CampaignCommand::kExplore);
  CheckOutputDirCommand(o.out, "explore");
  if (o.chunk < 0) throw io::InputError("--chunk " + std::to_string(o.chunk) + ": must be >= 0 (0 = 2 x threads)");
  const opt::CampaignDefinition& def = lc.config.definition;
  opt::Evaluator& evaluator = *lc.evaluator;
  const int threads = ResolveThreads(o.threads);
#ifdef _OPENMP
  // Also the physics inside one evaluation (used when samples run one at a time; inside the parallel sample
  // loop nested regions run on one thread), so --threads 1 is one core, as in optimize.
  omp_set_num_threads(threads);
#endif
  const int rank = MpiRank(), size = MpiSize();
  const int n = lc.config.explore.samples;
  CheckCampaignCost("explore", lc.resolved, lc.config.block, n, lc.config.block + ".samples", threads);

  opt::ConstraintSet cs(def, evaluator.QuantityNames());
  io::HistoryLayout layout{def.VariableNames(), evaluator.SeaNames(), cs.ReportedQuantities()};
  CampaignJournal journal(o.out, "samples.csv", layout, lc.config_hash, lc.resolved, cs, evaluator.QuantityNames().size());
  journal.Verify(evaluator, def);
  if (rank == 0) PrepareOutputDir(o.out, "explore", o.config, lc.resolved);
  journal.StartWriting();

  const auto xs = opt::SampleDesigns(def, lc.config.explore.method, n);
  const long logged = std::min<long>(journal.logged(), n);
  if (rank == 0 && !o.quiet && logged > 0) {
    std::fprintf(
        stderr, "explore: resuming: %ld samples in %s are replayed, not recomputed%s\n", logged,
        journal.path().c_str(),
        journal.truncated_tail() ? " (an incomplete last row from an interrupted run was discarded)" : "");
  }
  Progress progress("explore", n, rank == 0 && !o.quiet);
  auto add = [&](const opt::EvaluationRecord& rec) {
    journal.Add(rec);
    progress.Update(static_cast<long>(journal.records().size()), journal.replayed());
  };
  // Replay: sample i is row i; its inputs must be the ones the sampler gives now, bit for bit.
  if (rank == 0) {
    const auto replay = journal.Replay();
    for (long i = 0; i < logged; ++i) {
      try {
        const opt::EvaluationRecord* rec = opt::LookupReplay(replay, 0, static_cast<int>(i), xs[i]);
        if (rec == nullptr)
          throw opt::ReplayMismatch("row " + std::to_string(i) + " is not sample " + std::to_string(i));
        add(*rec);
      } catch (const opt::ReplayMismatch& e) {
        throw io::InputError(journal.path() +
                             ": cannot resume, the log does not match this campaign's samples: " + e.what() +
                             "; delete the file to start over");
      }
    }
  }
  auto make_record = [&](int i, const std::vector<double>& x, const opt::EvalResult& r, double wall) {
    opt::EvaluationRecord rec;
    rec.run = 0;
    rec.step = i;
    rec.x = x;
    rec.result = r;
    rec.wall_time_s = wall;
    rec.feasible = cs.Feasible(x, r, def.feasibility_tol);
    return rec;
  };
  if (size == 1) {
    opt::EvaluateInOrder(evaluator, xs, static_cast<int>(logged), n, threads, make_record, add);
  } else {
    // Rounds of size·chunk samples; rank r takes the r-th chunk; rank 0 logs the round in sample order.
    const int chunk = o.chunk > 0 ? o.chunk : 2 * threads;
    for (long base = logged; base < n; base += static_cast<long>(size) * chunk) {
      const long first = std::min<long>(n, base + static_cast<long>(rank) * chunk);
      const long last = std::min<long>(n, first + chunk);
      std::string rows;
      opt::EvaluateInOrder(evaluator, xs, static_cast<int>(first), static_cast<int>(last), threads,
                           make_record,
                           [&](const opt::EvaluationRecord& rec) { rows += journal.Serialise(rec); });
      const auto gathered = MpiGather(rows);
      for (const auto& part : gathered) {
        std::size_t pos = 0;
        while (pos < part.size()) {
          const std::size_t end = part.find('\n', pos);
          add(journal.Deserialise(part.substr(pos, end - pos)));
          pos = end + 1;
        }
      }
    }
  }
  if (rank != 0) return;

  const auto& recs = journal.records();
  progress.Finish(static_cast<long>(recs.size()), journal.replayed());
  std::vector<std::vector<double>> fx;
  std::vector<double> fy;
  long best = -1;
  for (std::size_t i = 0; i < recs.size(); ++i) {
    if (!recs[i].feasible) continue;
    fx.push_back(recs[i].x);
    fy.push_back(recs[i].result.objective);
    if (best < 0 || recs[i].result.objective < recs[best].result.objective) best = static_cast<long>(i);
  }
  nlohmann::json s;
  s["tool"] = std::string("hullopt ") + kVersion;
  s["command"] = "explore";
  s["method"] = lc.config.explore.method;
  s["samples"] = n;
  s["evaluations"] = recs.size();
  s["feasible_samples"] = fx.size();
  s["computed_evaluations"] = static_cast<long>(recs.size()) - journal.replayed();
  s["replayed_evaluations"] = journal.replayed();
  s["threads"] = threads;
  s["mpi_ranks"] = size;
  s["seed"] = def.seed;
  s["best_objective"] = best >= 0 ? nlohmann::json(recs[best].result.objective) : nlohmann::json();
  s["best_evaluation"] = best >= 0 ? nlohmann::json(best) : nlohmann::json();
  if (best >= 0) {
    nlohmann::json bv;
    for (std::size_t j = 0; j < def.variables.size(); ++j) bv[def.variables[j].name] = recs[best].x[j];
    s["best_variables"] = bv;
  }
  ReportWarnings(recs, best, journal.path(), o.quiet, &s);
  const std::string resolution_warning =
      best >= 0 ? CheckBestResolution(lc, recs[best].x, best, o.quiet, &s) : std::string();
  const auto names = def.VariableNames();
  try {
    const opt::SensitivityResult sens = opt::ComputeSensitivity(fx, fy, names);
    nlohmann::json sj;
    for (std::size_t j = 0; j < names.size(); ++j) {
      sj[names[j]] = {{"src", sens.src[j]}, {"first_order_sobol", sens.first_order[j]}};
    }
    s["sensitivity"] = sj;
    s["sensitivity_r_squared"] = sens.r_squared;
    io::WriteSensitivityCsv(OutPath(o.out, "sensitivity.csv"), names, sens);
  } catch (const std::invalid_argument& e) {
    s["sensitivity"] = nullptr;
    s["sensitivity_note"] = e.what();
    if (!o.quiet) std::fprintf(stderr, "explore: no sensitivity estimate: %s\n", e.what());
  }
  s["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  io::WriteJson(OutPath(o.out, "summary.json"), s);
  io::WriteExplorePlots(o.out, recs, names, evaluator.ObjectiveLabel());
  if (best >= 0) {
    char comment[200];
    std::snprintf(
        comment, sizeof comment,
        "hullopt explore: best sample of %s (evaluation %ld, objective %.10g); base config with its "
        "variable values",
        o.config.c_str(), best, recs[best].result.objective);
    io::WriteBestYaml(OutPath(o.out, "best.yaml"), lc.raw, lc.config.block, names, lc.config.start_source,
                      recs[best].x,
                      resolution_warning.empty() ? std::string(comment)
                                                 : std::string(comment) + "\n# WARNING: " + resolution_warning);
    WriteCampaignReport(o.out, "explore", o.config);
  }
  if (!o.quiet) {
    std::printf("%zu samples (%zu feasible)", recs.size(), fx.size());
    if (best >= 0) std::printf(", best objective %.10g at evaluation %ld", recs[best].result.objective, best);
    std::printf("\nwrote %s, summary.json, scatter.svg%s in %s\n", journal.path().c_str(),
                s["sensitivity"].is_null() ? "" : ", sensitivity.csv", o.out.c_str());
  }
}

}  // namespace

void AddExploreCommand(CLI::App& app) {
  auto o = std::make_shared<ExploreCliOptions>();
  auto* cmd = app.add_subcommand(
      "explore",
      "Evaluate a Sobol or Latin-hypercube sample of the design space in parallel and estimate sensitivities "
      "(resumable; mpirun -n N spreads samples over ranks)");
  cmd->add_option("config", o->config, "campaign YAML (explore: or optimize: block, with samples and method)")
      ->required();
  cmd->add_option("--out", o->out, "output folder (samples.csv, summary.json, sensitivity.csv)")->required();
  cmd->add_option("--threads", o->threads, "OpenMP threads per process (0 = OpenMP default)");
  cmd->add_option("--chunk", o->chunk, "samples per MPI rank and round (0 = 2 x threads)");
  cmd->add_flag("--quiet", o->quiet, "no progress output");
  cmd->callback([o] {
    const OutputFolderGuard lock(o->out, "explore", o->config);
    RunExplore(*o);
  });
}

}  // namespace hullopt::app
