// hullopt optimize CONFIG --out DIR: minimise the campaign objective over the free design variables with an
// NLopt algorithm (multistart, constraints), resumable, spread over MPI ranks by multistart run.
#include <nlohmann/json.hpp>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <chrono>
#include <cstdio>
#include <memory>

#include "app/campaign_journal.h"
#include "app/campaign_setup.h"
#include "app/campaign_report.h"
#include "app/commands.h"
#include "app/mpi_context.h"
#include "app/output_dir.h"
#include "app/pareto_sweep.h"
#include "app/progress.h"
#include "app/run_checks.h"
#include "hullopt/version.h"
#include "io/campaign_outputs.h"
#include "io/campaign_plots.h"
#include "io/input_error.h"
#include "optimizer/nlopt_algorithms.h"
#include "optimizer/nlopt_driver.h"

namespace hullopt::app {
namespace {

struct OptimizeOptions {
  std::string config;
  std::string out;
  int threads = 0;
  bool quiet = false;
};

nlohmann::json Named(const std::vector<std::string>& names, const std::vector<double>& values) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t i = 0; i < names.size() && i < values.size(); ++i) j[names[i]] = values[i];
  return j;
}

nlohmann::json RecordJson(const opt::EvaluationRecord& rec, long evaluation,
                          const opt::CampaignDefinition& def, const opt::Evaluator& ev,
                          const opt::ConstraintSet& cs) {
  nlohmann::json j;
  j["evaluation"] = evaluation;
  j["variables"] = Named(def.VariableNames(), rec.x);
  j["feasible"] = rec.feasible;
  if (rec.result.produced) {
    j["objective"] = rec.result.objective;
    j["seas"] = Named(ev.SeaNames(), rec.result.sea_values);
    j["constrained_quantities"] = Named(cs.ReportedQuantities(), cs.ReportedValues(rec.result));
  } else {
    j["objective"] = nullptr;
    j["refused"] = rec.result.error;
  }
  return j;
}

void RunOptimize(const OptimizeOptions& o) {
  const auto wall0 = std::chrono::steady_clock::now();
  LoadedCampaign lc = LoadCampaign(o.config, io::CampaignCommand::kOptimize);
  CheckOutputDirCommand(o.out, "optimize");
  const opt::CampaignDefinition& def = lc.config.definition;
  opt::Evaluator& evaluator = *lc.evaluator;
  const int threads = ResolveThreads(o.threads);
  CheckCampaignCost("optimize", lc.resolved, lc.config.block,
                    1 + static_cast<long>(def.starts) *
                            (def.stopping.max_evaluations + (def.polish_algorithm.empty() ? 0 : def.polish_max_evaluations)),
                    lc.config.block + ".starts x max_evaluations", 1);
#ifdef _OPENMP
  omp_set_num_threads(threads);  // for the physics inside one evaluation
#endif
  const int rank = MpiRank(), size = MpiSize();

  opt::ConstraintSet cs(def, evaluator.QuantityNames());
  io::HistoryLayout layout{def.VariableNames(), evaluator.SeaNames(), cs.ReportedQuantities()};
  CampaignJournal journal(o.out, "history.csv", layout, lc.config_hash, lc.resolved, cs, evaluator.QuantityNames().size());
  journal.Verify(evaluator, def);

  opt::NloptDriver driver(def, evaluator);
  const long per_run = def.stopping.max_evaluations + (def.polish_algorithm.empty() ? 0 : def.polish_max_evaluations);
  Progress progress("optimize", 1L + static_cast<long>(def.starts) * per_run,
                    rank == 0 && !o.quiet);
  auto add = [&](const opt::EvaluationRecord& rec) {
    journal.Add(rec);
    progress.Update(static_cast<long>(journal.records().size()), journal.replayed());
  };
  auto resume_error = [&](const opt::ReplayMismatch& e) {
    return io::InputError(journal.path() +
                          ": cannot resume, the log does not match this campaign's sequence: " + e.what() +
                          "; delete the file to start over");
  };

  // Baseline (evaluation 0): the base design. A local algorithm must start from a design that exists and
  // satisfies the constraints; this is checked before anything is written or optimised.
  std::string baseline_problem;
  opt::EvaluationRecord baseline;
  if (rank == 0) {
    try {
      baseline = driver.EvaluateBaseline(journal.Replay(), nullptr);  // logged once the start is accepted
    } catch (const opt::ReplayMismatch& e) {
      throw resume_error(e);
    }
    if (!opt::IsGlobal(def.algorithm) && !baseline.feasible) {
      if (!baseline.result.produced) {
        baseline_problem = "the base design (start point) is refused: " + baseline.result.error;
      } else {
        std::string violated;
        const auto g = cs.Values(baseline.x, baseline.result);
        for (std::size_t j = 0; j < g.size(); ++j) {
          if (g[j] > def.feasibility_tol) {
            const auto& c = def.constraints[j];
            violated += (violated.empty() ? "" : ", ") + c.key + " = " + std::to_string(c.limit);
          }
        }
        baseline_problem = "the base design (start point) violates " + violated;
      }
      baseline_problem = o.config + ": " + lc.config.block + ": " + baseline_problem + "; local algorithm " +
                         def.algorithm + " needs a feasible start (change the start or use a GN_* algorithm)";
    }
  }
  baseline_problem = MpiBroadcast(baseline_problem);
  if (!baseline_problem.empty()) throw io::InputError(baseline_problem);

  // The campaign is accepted: from here on every evaluation is logged.
  if (rank == 0) PrepareOutputDir(o.out, "optimize", o.config, lc.resolved);
  journal.StartWriting();
  if (rank == 0 && !o.quiet && journal.logged() > 0) {
    std::fprintf(
        stderr, "optimize: resuming: %ld evaluations in %s are replayed, not recomputed%s\n",
        journal.logged(), journal.path().c_str(),
        journal.truncated_tail() ? " (an incomplete last row from an interrupted run was discarded)" : "");
  }
  if (rank == 0) add(baseline);

  // Multistart runs, round-robin over MPI ranks; rank 0 logs them in run order after each round.
  nlohmann::json runs = nlohmann::json::array();
  for (int round = 0; round * size < def.starts; ++round) {
    const int run = round * size + rank;
    std::string payload;
    if (run < def.starts) {
      std::string rows;
      opt::RecordSink sink;
      if (size == 1) {
        sink = add;
      } else {
        sink = [&](const opt::EvaluationRecord& rec) { rows += journal.Serialise(rec); };
      }
      opt::RunResult rr;
      try {
        rr = driver.Run(run, journal.Replay(), sink);
      } catch (const opt::ReplayMismatch& e) {
        throw resume_error(e);
      }
      nlohmann::json j;
      j["run"] = rr.run;
      j["start"] = Named(def.VariableNames(), rr.start);
      j["evaluations"] = rr.evaluations;
      j["status"] = rr.status;
      if (!def.polish_algorithm.empty()) {
        j["polish_algorithm"] = def.polish_algorithm;
        j["polish_evaluations"] = rr.polish_evaluations;
        j["polish_status"] = rr.polish_status.empty() ? "SKIPPED (no feasible point)" : rr.polish_status;
      }
      j["found_feasible"] = rr.found_feasible;
      if (rr.found_feasible) {
        j["best_objective"] = rr.best_objective;
        j["best_variables"] = Named(def.VariableNames(), rr.best_x);
      }
      j["rows"] = rows;
      payload = j.dump();
    }
    const auto gathered = MpiGather(payload);
    if (rank != 0) continue;
    for (const auto& p : gathered) {
      if (p.empty()) continue;
      nlohmann::json j = nlohmann::json::parse(p);
      const std::string rows = j["rows"].get<std::string>();
      std::size_t pos = 0;
      while (pos < rows.size()) {
        const std::size_t end = rows.find('\n', pos);
        add(journal.Deserialise(rows.substr(pos, end - pos)));
        pos = end + 1;
      }
      j.erase("rows");
      runs.push_back(j);
    }
  }
  if (rank != 0) return;

  const auto& recs = journal.records();
  progress.Finish(static_cast<long>(recs.size()), journal.replayed());
  long best = -1;
  for (std::size_t i = 0; i < recs.size(); ++i) {
    if (recs[i].feasible && (best < 0 || recs[i].result.objective < recs[best].result.objective)) {
      best = static_cast<long>(i);
    }
  }
  nlohmann::json s;
  s["tool"] = std::string("hullopt ") + kVersion;
  s["command"] = "optimize";
  s["algorithm"] = def.algorithm;
  if (!def.polish_algorithm.empty()) s["polish_algorithm"] = def.polish_algorithm;
  s["evaluations"] = recs.size();
  s["computed_evaluations"] = static_cast<long>(recs.size()) - journal.replayed();
  s["replayed_evaluations"] = journal.replayed();
  s["starts"] = def.starts;
  s["seed"] = def.seed;
  s["threads"] = threads;
  s["mpi_ranks"] = size;
  s["baseline_objective"] =
      baseline.result.produced ? nlohmann::json(baseline.result.objective) : nlohmann::json();
  s["baseline_feasible"] = baseline.feasible;
  s["baseline"] = RecordJson(baseline, 0, def, evaluator, cs);
  if (best >= 0) {
    s["best_objective"] = recs[best].result.objective;
    s["best_evaluation"] = best;
    s["best"] = RecordJson(recs[best], best, def, evaluator, cs);
  } else {
    s["best_objective"] = nullptr;
    s["best_evaluation"] = nullptr;
  }
  s["runs"] = runs;
  ReportWarnings(recs, best, journal.path(), o.quiet, &s);
  const std::string resolution_warning =
      best >= 0 ? CheckBestResolution(lc, recs[best].x, best, o.quiet, &s) : std::string();
  s["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  io::WriteJson(OutPath(o.out, "summary.json"), s);
  io::WriteOptimizePlots(o.out, recs, def.VariableNames(), def.LowerBounds(), def.UpperBounds(),
                         evaluator.ObjectiveLabel());
  if (best >= 0) {
    char comment[200];
    std::snprintf(
        comment, sizeof comment,
        "hullopt optimize: best design of %s (evaluation %ld, objective %.10g); base config with the "
        "best variable values",
        o.config.c_str(), best, recs[best].result.objective);
    io::WriteBestYaml(OutPath(o.out, "best.yaml"), lc.raw, lc.config.block, def.VariableNames(),
                      lc.config.start_source, recs[best].x,
                      resolution_warning.empty() ? std::string(comment)
                                                 : std::string(comment) + "\n# WARNING: " + resolution_warning);
    WriteCampaignReport(o.out, "optimize", o.config);
  }
  if (!o.quiet) {
    if (best >= 0) {
      std::printf("best objective %.10g at evaluation %ld of %zu (baseline %.10g)\n",
                  recs[best].result.objective, best, recs.size(),
                  baseline.result.produced ? baseline.result.objective : NAN);
    } else {
      std::printf("no feasible design found in %zu evaluations\n", recs.size());
    }
    std::printf("wrote %s, best.yaml, summary.json, convergence.svg, variables.svg in %s\n",
                journal.path().c_str(), o.out.c_str());
  }
}

}  // namespace

void AddOptimizeCommand(CLI::App& app) {
  auto o = std::make_shared<OptimizeOptions>();
  auto* cmd = app.add_subcommand(
      "optimize",
      "Minimise the campaign objective over the free design variables (NLopt; resumable: re-run the same "
      "command to continue an interrupted campaign; mpirun -n N spreads multistart runs over ranks)");
  cmd->add_option("config", o->config, "campaign YAML (optimize: block)")->required();
  cmd->add_option("--out", o->out, "output folder (history.csv, best.yaml, summary.json)")->required();
  cmd->add_option("--threads", o->threads, "OpenMP threads per process (0 = OpenMP default)");
  cmd->add_flag("--quiet", o->quiet, "no progress output");
  cmd->callback([o] {
    // One lock on the campaign folder for the whole run (a Pareto sweep's runs live inside it).
    const OutputFolderGuard lock(o->out, "optimize", o->config);
    if (!HasParetoSweep(o->config)) return RunOptimize(*o);
    RunParetoSweep(o->config, o->out, [o](const std::string& config, const std::string& out) {
      OptimizeOptions one = *o;
      one.config = config;
      one.out = out;
      RunOptimize(one);
    });
  });
}

}  // namespace hullopt::app
