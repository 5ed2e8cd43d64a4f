// The explore campaign: evaluate a Sobol or Latin-hypercube sample of the design box in parallel (OpenMP
// threads, processes), log samples.csv in sample order (identical for any thread/process count), and estimate
// the sensitivity of the objective to each variable. Resumable like optimize.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "campaign/campaign_kinds.h"
#include "io/config/output_folder.h"
#include "io/config/campaign_outputs.h"
#include "io/report/campaign_plots.h"
#include "io/formats/input_error.h"
#include "optimizer/design_sampling.h"
#include "optimizer/parallel_evaluation.h"
#include "optimizer/sensitivity.h"

namespace hullopt::campaign {
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
      io::WriteSensitivityCsv(io::OutPath(r.options().out, "sensitivity.csv"), names, sens);
    } catch (const std::invalid_argument& e) {
      s["sensitivity"] = nullptr;
      s["sensitivity_note"] = e.what();
      r.Note(std::string("explore: no sensitivity estimate: ") + e.what());
    }
  }

  void WritePlots(const CampaignRunner& r) const override {
    io::WriteExplorePlots(r.options().out, r.journal().records(), r.definition().VariableNames(),
                          r.evaluator().ObjectiveLabel());
  }

  std::string ResultText(const CampaignRunner& r, long best, const nlohmann::json& s) const override {
    const auto& recs = r.journal().records();
    char line[200];
    std::snprintf(line, sizeof line, "%zu samples (%zu feasible)", recs.size(), fx_.size());
    std::string text = line;
    if (best >= 0) {
      std::snprintf(line, sizeof line, ", best objective %.10g at evaluation %ld", recs[best].result.objective, best);
      text += line;
    }
    return text + "\nwrote " + r.journal().path() + ", summary.json, scatter.svg" +
           (s["sensitivity"].is_null() ? "" : ", sensitivity.csv") + " in " + r.options().out + "\n";
  }

 private:
  int chunk_;
  std::vector<std::vector<double>> fx_;  ///< the feasible samples' variables
};

}  // namespace

std::unique_ptr<CampaignKind> MakeExploreCampaign(int chunk) { return std::make_unique<ExploreCampaign>(chunk); }

}  // namespace hullopt::campaign
