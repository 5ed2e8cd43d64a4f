// hullopt explore CONFIG --out DIR: evaluate a Sobol or Latin-hypercube sample of the design box in parallel
// (OpenMP threads, MPI ranks), log samples.csv in sample order (identical for any thread/rank count),
// and estimate the sensitivity of the objective to each variable. Resumable like optimize.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/campaign_runner.h"
#include "app/commands.h"
#include "app/output_dir.h"
#include "io/config/campaign_outputs.h"
#include "io/report/campaign_plots.h"
#include "io/formats/input_error.h"
#include "optimizer/design_sampling.h"
#include "optimizer/parallel_evaluation.h"
#include "optimizer/sensitivity.h"

namespace hullopt::app {
namespace {

// The sample of the design box, in sample order; under MPI in chunks of samples, one unit of work each.
class ExploreCampaign : public CampaignKind {
 public:
  explicit ExploreCampaign(int chunk) : chunk_(chunk) {}
  Words Wording() const override {
    return {"explore", "samples.csv", "samples", "samples", "best sample", "base config with its variable values"};
  }
  io::CampaignCommand ConfigCommand() const override { return io::CampaignCommand::kExplore; }

  void CheckOptions() const override {
    if (chunk_ < 0) throw io::InputError("--chunk " + std::to_string(chunk_) + ": must be >= 0 (0 = 2 x threads)");
  }
  CampaignSize Size(const LoadedCampaign& lc, int threads) const override {
    return {lc.config.explore.samples, lc.config.block + ".samples", threads};
  }
  long Resumed(const CampaignRunner& r) const override {
    return std::min<long>(r.journal().logged(), r.campaign().config.explore.samples);
  }

  void Run(CampaignRunner& r) override {
    const opt::CampaignDefinition& def = r.definition();
    const int n = r.campaign().config.explore.samples;
    const auto xs = opt::SampleDesigns(def, r.campaign().config.explore.method, n);
    const long logged = Resumed(r);
    // Replay: sample i is row i; its inputs must be the ones the sampler gives now, bit for bit.
    if (r.rank() == 0) {
      const auto replay = r.journal().Replay();
      for (long i = 0; i < logged; ++i) {
        try {
          const opt::EvaluationRecord* rec = opt::LookupReplay(replay, 0, static_cast<int>(i), xs[i]);
          if (rec == nullptr)
            throw opt::ReplayMismatch("row " + std::to_string(i) + " is not sample " + std::to_string(i));
          r.Add(*rec);
        } catch (const opt::ReplayMismatch& e) {
          throw r.ResumeError(e);
        }
      }
    }
    auto make_record = [&](int i, const std::vector<double>& x, const opt::EvalResult& res, double wall) {
      opt::EvaluationRecord rec;
      rec.run = 0;
      rec.step = i;
      rec.x = x;
      rec.result = res;
      rec.wall_time_s = wall;
      rec.feasible = r.constraints().Feasible(x, res, def.feasibility_tol);
      return rec;
    };
    // One process: all remaining samples in one unit. Several: chunks of samples (rounds of size·chunk).
    const long remaining = n - logged;
    const long chunk = r.size() == 1 ? std::max(1L, remaining) : (chunk_ > 0 ? chunk_ : 2 * r.threads());
    const int units = static_cast<int>((remaining + chunk - 1) / chunk);
    r.Split(units, [&](int unit, const opt::RecordSink& sink) {
      const long first = logged + unit * chunk;
      const long last = std::min<long>(n, first + chunk);
      opt::EvaluateInOrder(r.evaluator(), xs, static_cast<int>(first), static_cast<int>(last), r.threads(),
                           make_record, sink);
      return nlohmann::json::object();
    });
  }

  void Summarise(const CampaignRunner& r, long best, nlohmann::json* summary) override {
    const opt::CampaignDefinition& def = r.definition();
    const auto& recs = r.journal().records();
    const bool quiet = r.options().quiet;
    nlohmann::json& s = *summary;
    fx_.clear();
    std::vector<double> fy;
    for (const auto& rec : recs) {
      if (!rec.feasible) continue;
      fx_.push_back(rec.x);
      fy.push_back(rec.result.objective);
    }
    s["method"] = r.campaign().config.explore.method;
    s["samples"] = r.campaign().config.explore.samples;
    s["feasible_samples"] = fx_.size();
    if (best >= 0) {
      nlohmann::json bv;
      for (std::size_t j = 0; j < def.variables.size(); ++j) bv[def.variables[j].name] = recs[best].x[j];
      s["best_variables"] = bv;
    }
    const auto names = def.VariableNames();
    try {
      const opt::SensitivityResult sens = opt::ComputeSensitivity(fx_, fy, names);
      nlohmann::json sj;
      for (std::size_t j = 0; j < names.size(); ++j) {
        sj[names[j]] = {{"src", sens.src[j]}, {"first_order_sobol", sens.first_order[j]}};
      }
      s["sensitivity"] = sj;
      s["sensitivity_r_squared"] = sens.r_squared;
      io::WriteSensitivityCsv(OutPath(r.options().out, "sensitivity.csv"), names, sens);
    } catch (const std::invalid_argument& e) {
      s["sensitivity"] = nullptr;
      s["sensitivity_note"] = e.what();
      if (!quiet) std::fprintf(stderr, "explore: no sensitivity estimate: %s\n", e.what());
    }
  }

  void WritePlots(const CampaignRunner& r) const override {
    io::WriteExplorePlots(r.options().out, r.journal().records(), r.definition().VariableNames(),
                          r.evaluator().ObjectiveLabel());
  }

  void PrintResult(const CampaignRunner& r, long best, const nlohmann::json& s) const override {
    const auto& recs = r.journal().records();
    std::printf("%zu samples (%zu feasible)", recs.size(), fx_.size());
    if (best >= 0) std::printf(", best objective %.10g at evaluation %ld", recs[best].result.objective, best);
    std::printf("\nwrote %s, summary.json, scatter.svg%s in %s\n", r.journal().path().c_str(),
                s["sensitivity"].is_null() ? "" : ", sensitivity.csv", r.options().out.c_str());
  }

 private:
  int chunk_;
  std::vector<std::vector<double>> fx_;  ///< the feasible samples' variables
};

}  // namespace

void AddExploreCommand(CLI::App& app) {
  auto chunk = std::make_shared<int>(0);
  AddCampaignCommand(
      app,
      {"explore",
       "Evaluate a Sobol or Latin-hypercube sample of the design space in parallel and estimate sensitivities "
       "(resumable; mpirun -n N spreads samples over ranks)",
       "campaign YAML (explore: or optimize: block, with samples and method)", "config",
       "output folder (samples.csv, summary.json, sensitivity.csv)"},
      [chunk](const CampaignCliOptions& o) {
        ExploreCampaign kind(*chunk);
        RunCampaign(kind, o);
      },
      [chunk](CLI::App* cmd) {
        cmd->add_option("--chunk", *chunk, "samples per MPI rank and round (0 = 2 x threads)");
      });
}

}  // namespace hullopt::app
