// The optimize campaign: minimise the campaign objective over the free design variables with an NLopt
// algorithm (multistart, constraints), resumable, spread over processes by multistart run.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "campaign/campaign_kinds.h"
#include "io/report/campaign_plots.h"
#include "optimizer/nlopt_algorithms.h"
#include "optimizer/nlopt_driver.h"

namespace hullopt::campaign {
namespace {

nlohmann::json RecordJson(const opt::EvaluationRecord& rec, long evaluation, const CampaignRunner& r) {
  nlohmann::json j;
  j["evaluation"] = evaluation;
  j["variables"] = NamedValues(r.definition().VariableNames(), rec.x);
  j["feasible"] = rec.feasible;
  if (rec.result.produced) {
    j["objective"] = rec.result.objective;
    j["seas"] = NamedValues(r.evaluator().SeaNames(), rec.result.sea_values);
    j["constrained_quantities"] =
        NamedValues(r.constraints().ReportedQuantities(), r.constraints().ReportedValues(rec.result));
  } else {
    j["objective"] = nullptr;
    j["refused"] = rec.result.error;
  }
  return j;
}

// Evaluation 0 is the base design; then the multistart runs, one unit of work each: over the threads of one
// process or the ranks of several (CampaignRunner::Split), logged in run order either way.
class OptimizeCampaign : public CampaignKind {
 public:
  Words Wording() const override {
    return {"optimize",    "history.csv", "evaluations", "sequence",
            "best design", "base config with the best variable values"};
  }
  io::CampaignCommand ConfigCommand() const override { return io::CampaignCommand::kOptimize; }

  // The multistart runs run on the threads (CampaignRunner::Split), up to min(threads, starts) at once.
  CampaignSize Size(const LoadedCampaign& lc, int threads) const override {
    const opt::CampaignDefinition& def = lc.config.definition;
    const long per_run =
        def.stopping.max_evaluations + (def.polish_algorithm.empty() ? 0 : def.polish_max_evaluations);
    return {1 + static_cast<long>(def.starts) * per_run, lc.config.block + ".starts x max_evaluations",
            std::max(1, std::min(threads, def.starts))};
  }

  // A local algorithm must start from a design that exists and satisfies the constraints; this is checked
  // before anything is written or optimised.
  std::string Accept(CampaignRunner& r) override {
    driver_ = std::make_unique<opt::NloptDriver>(r.definition(), r.evaluator());
    if (r.rank() != 0) return "";
    const opt::CampaignDefinition& def = r.definition();
    try {
      baseline_ = driver_->EvaluateBaseline(r.journal().Replay(), nullptr);  // logged once the start is accepted
    } catch (const opt::ReplayMismatch& e) {
      throw r.ResumeError(e);
    }
    if (opt::IsGlobal(def.algorithm) || baseline_.feasible) return "";
    std::string problem;
    if (!baseline_.result.produced) {
      problem = "the base design (start point) is refused: " + baseline_.result.error;
    } else {
      std::string violated;
      const auto g = r.constraints().Values(baseline_.x, baseline_.result);
      for (std::size_t j = 0; j < g.size(); ++j) {
        if (g[j] > def.feasibility_tol) {
          const auto& c = def.constraints[j];
          violated += (violated.empty() ? "" : ", ") + c.key + " = " + std::to_string(c.limit);
        }
      }
      problem = "the base design (start point) violates " + violated;
    }
    return r.config_name() + ": " + r.campaign().config.block + ": " + problem + "; local algorithm " +
           def.algorithm + " needs a feasible start (change the start or use a GN_* algorithm)";
  }

  void Run(CampaignRunner& r) override {
    const opt::CampaignDefinition& def = r.definition();
    if (r.rank() == 0) r.Add(baseline_);
    runs_ = r.Split(def.starts, [&](int run, const opt::RecordSink& sink) {
      opt::RunResult rr;
      try {
        rr = driver_->Run(run, r.journal().Replay(), sink);
      } catch (const opt::ReplayMismatch& e) {
        throw r.ResumeError(e);
      }
      nlohmann::json j;
      j["run"] = rr.run;
      j["start"] = NamedValues(def.VariableNames(), rr.start);
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
        j["best_variables"] = NamedValues(def.VariableNames(), rr.best_x);
      }
      return j;
    });
  }

  void Summarise(const CampaignRunner& r, long best, nlohmann::json* summary) override {
    const opt::CampaignDefinition& def = r.definition();
    nlohmann::json& s = *summary;
    s["algorithm"] = def.algorithm;
    if (!def.polish_algorithm.empty()) s["polish_algorithm"] = def.polish_algorithm;
    s["starts"] = def.starts;
    s["baseline_objective"] =
        baseline_.result.produced ? nlohmann::json(baseline_.result.objective) : nlohmann::json();
    s["baseline_feasible"] = baseline_.feasible;
    s["baseline"] = RecordJson(baseline_, 0, r);
    if (best >= 0) s["best"] = RecordJson(r.journal().records()[best], best, r);
    s["runs"] = runs_;
  }

  void WritePlots(const CampaignRunner& r) const override {
    const opt::CampaignDefinition& def = r.definition();
    io::WriteOptimizePlots(r.options().out, r.journal().records(), def.VariableNames(), def.LowerBounds(),
                           def.UpperBounds(), r.evaluator().ObjectiveLabel());
  }

  std::string ResultText(const CampaignRunner& r, long best, const nlohmann::json&) const override {
    const auto& recs = r.journal().records();
    char line[200];
    if (best >= 0) {
      std::snprintf(line, sizeof line, "best objective %.10g at evaluation %ld of %zu (baseline %.10g)\n",
                    recs[best].result.objective, best, recs.size(),
                    baseline_.result.produced ? baseline_.result.objective : NAN);
    } else {
      std::snprintf(line, sizeof line, "no feasible design found in %zu evaluations\n", recs.size());
    }
    return line + ("wrote " + r.journal().path() + ", best.yaml, summary.json, convergence.svg, variables.svg in " +
                   r.options().out + "\n");
  }

 private:
  std::unique_ptr<opt::NloptDriver> driver_;
  opt::EvaluationRecord baseline_;
  std::vector<nlohmann::json> runs_;
};

}  // namespace

std::unique_ptr<CampaignKind> MakeOptimizeCampaign() { return std::make_unique<OptimizeCampaign>(); }

}  // namespace hullopt::campaign
