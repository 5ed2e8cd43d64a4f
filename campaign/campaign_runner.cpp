#include "campaign/campaign_runner.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <mutex>

#include "hullopt/version.h"
#include "io/config/campaign_outputs.h"
#include "io/config/output_folder.h"

namespace hullopt::campaign {

long CampaignKind::Resumed(const CampaignRunner& runner) const { return runner.journal().logged(); }

std::string CampaignKind::Accept(CampaignRunner&) { return ""; }

nlohmann::json NamedValues(const std::vector<std::string>& names, const std::vector<double>& values) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t i = 0; i < names.size() && i < values.size(); ++i) j[names[i]] = values[i];
  return j;
}

CampaignRunner::CampaignRunner(CampaignKind& kind, const CampaignSpec& spec, const CampaignRunOptions& options)
    : kind_(kind),
      words_(kind.Wording()),
      spec_(spec),
      options_(options),
      comm_(options.comm ? *options.comm : SerialComm()),
      wall0_(std::chrono::steady_clock::now()),
      campaign_(LoadCampaign(spec)) {}

void CampaignRunner::Note(const std::string& line) const {
  if (rank_ == 0 && !options_.quiet && options_.message) options_.message(line);
}

void CampaignRunner::Progress(CampaignProgress::Stage stage) const {
  if (rank_ != 0 || options_.quiet || !options_.progress) return;
  CampaignProgress p;
  p.stage = stage;
  p.label = words_.command;
  p.total = total_;
  p.done = journal_ ? static_cast<long>(journal_->records().size()) : 0;
  p.replayed = journal_ ? journal_->replayed() : 0;
  options_.progress(p);
}

void CampaignRunner::Add(const opt::EvaluationRecord& rec) {
  const auto t0 = std::chrono::steady_clock::now();
  journal_->Add(rec);
  if (!rec.replayed && rec.result.cost.measured) {
    for (int s = 0; s < static_cast<int>(opt::CostStage::kCount); ++s) cost_.seconds[s] += rec.result.cost.seconds[s];
    ++costed_;
    costed_wall_s_ += rec.wall_time_s;
    log_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  Progress(CampaignProgress::Stage::kUpdate);
  if (options_.max_evaluations > 0 &&
      static_cast<long>(journal_->records().size()) - journal_->replayed() >= options_.max_evaluations)
    throw EvaluationLimitReached{};
}

io::InputError CampaignRunner::ResumeError(const opt::ReplayMismatch& e) const {
  return io::InputError(journal_->path() + ": cannot resume, the log does not match this campaign's " +
                        words_.sequence + ": " + e.what() + "; delete the file to start over");
}

std::vector<nlohmann::json> CampaignRunner::SplitOverThreads(int units, const UnitWork& work) {
  // The units run on the threads; the head unit (the lowest one not finished) hands its records straight to
  // Add, later units keep theirs until every unit before them is finished, so Add sees the sequence order of
  // one thread. Add (the log, progress) runs under the lock, one record at a time.
  std::vector<nlohmann::json> reports(units);
  std::vector<std::vector<opt::EvaluationRecord>> waiting(units);
  std::vector<char> finished(units, 0);
  int head = 0;
  std::mutex mutex;
  std::exception_ptr error;  // the first failure (or EvaluationLimitReached); the other units stop at their next record
  struct Stopped {};         // thrown into a unit's work once another unit has failed
  const int nthreads = threads_;
  (void)nthreads;  // read only by the OpenMP pragma; a build without OpenMP runs the units in order
#pragma omp parallel for schedule(dynamic, 1) num_threads(nthreads)
  for (int unit = 0; unit < units; ++unit) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (error) continue;
    }
    try {
      opt::RecordSink sink = [&, unit](const opt::EvaluationRecord& rec) {
        std::lock_guard<std::mutex> lock(mutex);
        if (error) throw Stopped{};
        if (unit != head) {
          waiting[unit].push_back(rec);
          return;
        }
        try {
          Add(rec);
        } catch (...) {
          error = std::current_exception();
          throw Stopped{};
        }
      };
      nlohmann::json j = work(unit, sink);
      std::lock_guard<std::mutex> lock(mutex);
      reports[unit] = std::move(j);
      finished[unit] = 1;
      while (!error && head < units && finished[head]) {
        if (++head == units) break;
        try {
          for (const opt::EvaluationRecord& rec : waiting[head]) Add(rec);
        } catch (...) {
          error = std::current_exception();
        }
        waiting[head].clear();
      }
    } catch (const Stopped&) {
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
  return reports;
}

std::vector<nlohmann::json> CampaignRunner::Split(int units, const UnitWork& work) {
  if (size_ == 1 && threads_ > 1 && units > 1 && evaluator().IsThreadSafe()) return SplitOverThreads(units, work);
  std::vector<nlohmann::json> reports;
  for (int round = 0; round * size_ < units; ++round) {
    const int unit = round * size_ + rank_;
    std::string payload;  // empty: this rank has no unit in this round
    if (unit < units) {
      std::string rows;
      opt::RecordSink sink;
      if (size_ == 1) {
        sink = [this](const opt::EvaluationRecord& rec) { Add(rec); };
      } else {
        sink = [&](const opt::EvaluationRecord& rec) { rows += journal_->Serialise(rec); };
      }
      nlohmann::json j = work(unit, sink);
      j["rows"] = rows;
      payload = j.dump();
    }
    const auto gathered = comm_.Gather(payload);
    if (rank_ != 0) continue;
    for (const auto& p : gathered) {
      if (p.empty()) continue;
      nlohmann::json j = nlohmann::json::parse(p);
      const std::string rows = j["rows"].get<std::string>();
      std::size_t pos = 0;
      while (pos < rows.size()) {
        const std::size_t end = rows.find('\n', pos);
        Add(journal_->Deserialise(rows.substr(pos, end - pos)));
        pos = end + 1;
      }
      j.erase("rows");
      reports.push_back(j);
    }
  }
  return reports;
}

void CampaignRunner::Start() {
  const std::string& command = words_.command;
  io::CheckOutputDirCommand(options_.out, command);
  kind_.CheckOptions();
  threads_ = ResolveThreads(options_.threads);
#ifdef _OPENMP
  // For the physics inside one evaluation too (nested regions inside a parallel loop over designs run on one
  // thread), so --threads 1 is one core.
  omp_set_num_threads(threads_);
#endif
  rank_ = comm_.Rank();
  size_ = comm_.Size();
  if (options_.max_evaluations > 0 && size_ > 1)
    throw io::InputError(command + ": max_evaluations stops a campaign of one process only (" +
                         std::to_string(size_) + " processes)");
  const CampaignSize size = kind_.Size(campaign_, threads_);
  const std::string cost = CheckCampaignCost(command, campaign_.resolved, campaign_.config.block, size.evaluations,
                                             size.count_key, size.parallel, options_.force);
  if (rank_ == 0 && !cost.empty() && options_.message) options_.message(cost);

  const opt::CampaignDefinition& def = definition();
  opt::Evaluator& ev = evaluator();
  constraints_ = std::make_unique<opt::ConstraintSet>(def, ev.QuantityNames());
  io::HistoryLayout layout{def.VariableNames(), ev.SeaNames(), constraints_->ReportedQuantities()};
  journal_ = std::make_unique<CampaignJournal>(comm_, options_.out, words_.log_file, layout, campaign_.config_hash,
                                               campaign_.resolved, *constraints_, ev.QuantityNames().size());
  if (!options_.resume && journal_->logged() > 0)
    throw io::InputError(journal_->path() + ": holds " + std::to_string(journal_->logged()) + " " +
                         words_.resumed + " of this campaign and resume is off: resume it, use another output "
                         "folder, or delete the file to start over");
  journal_->Verify(ev, def);
  total_ = size.evaluations;
  Progress(CampaignProgress::Stage::kStart);

  // Nothing is written before the campaign is accepted; from then on every evaluation is logged.
  const std::string problem = comm_.Broadcast(kind_.Accept(*this));
  if (!problem.empty()) throw io::InputError(problem);
  if (rank_ == 0) io::PrepareOutputDir(options_.out, command, spec_.Name(), campaign_.resolved);
  journal_->StartWriting();
  const long resumed = kind_.Resumed(*this);
  if (resumed > 0) {
    Note(command + ": resuming: " + std::to_string(resumed) + " " + words_.resumed + " in " + journal_->path() +
         " are replayed, not recomputed" +
         (journal_->truncated_tail() ? " (an incomplete last row from an interrupted run was discarded)" : ""));
  }
}

namespace {

/// A variable within this share of its range from a bound is at the bound; a constraint within this share of
/// max(|limit|, 1) from its limit is active. Coarser than the optimiser's own tolerances on purpose: a report
/// line for a design the optimiser left a hair inside its bound.
constexpr double kActiveFraction = 1e-3;

/// The one-sided step beyond a bound for the gain of relaxing it: this share of the variable's range.
constexpr double kRelaxStepFraction = 0.01;

/// Variables at a bound (with the objective change of moving the bound by kRelaxStepFraction of the range, one
/// evaluation each, when `evaluator` is given) and active constraints (their gain is not computed).
std::vector<std::string> ActiveSet(const opt::CampaignDefinition& def, const std::vector<std::string>& quantities,
                                   const opt::EvaluationRecord& best, opt::Evaluator* evaluator) {
  std::vector<std::string> lines;
  char b[600];
  for (std::size_t i = 0; i < def.variables.size() && i < best.x.size(); ++i) {
    const auto& v = def.variables[i];
    const double tol = kActiveFraction * (v.upper - v.lower);
    const bool lo = best.x[i] <= v.lower + tol, hi = best.x[i] >= v.upper - tol;
    if (!lo && !hi) continue;
    std::snprintf(b, sizeof b, "design variable %s = %.6g at its %s bound (range %.6g..%.6g)", v.name.c_str(),
                  best.x[i], lo ? "lower" : "upper", v.lower, v.upper);
    std::string line = b;
    if (evaluator) {
      std::vector<double> x = best.x;
      const double step = kRelaxStepFraction * (v.upper - v.lower);
      x[i] = lo ? v.lower - step : v.upper + step;
      const opt::EvalResult r = opt::EvaluateSafely(*evaluator, x);
      if (r.produced) {
        std::snprintf(b, sizeof b,
                      "; relaxing it by 1 %% of the range to %.6g changes the objective from %.6g to %.6g "
                      "(%+.3g; constraints not re-checked)",
                      x[i], best.result.objective, r.objective, r.objective - best.result.objective);
        line += b;
        if (r.objective >= best.result.objective) line += ": no gain, the bound does not hold the optimum back";
      } else {
        line += "; relaxing it: the design beyond the bound is refused (" + r.error + ")";
      }
    } else {
      line += "; gain of relaxing it not computed";
    }
    lines.push_back(line);
  }
  for (const auto& c : def.constraints) {
    for (std::size_t q = 0; q < quantities.size() && q < best.result.quantities.size(); ++q) {
      if (quantities[q] != c.quantity) continue;
      const double value = best.result.quantities[q];
      const double scale = std::max(std::fabs(c.limit), 1.0);
      if (std::fabs(value - c.limit) > kActiveFraction * scale) continue;
      std::snprintf(b, sizeof b, "constraint %s = %.6g active: %s = %.6g (gain of relaxing it not computed)",
                    c.key.c_str(), c.limit, c.quantity.c_str(), value);
      lines.push_back(b);
    }
  }
  return lines;
}

}  // namespace

void CampaignRunner::Finish(CampaignResult* result) {
  const std::string& command = words_.command;
  const opt::CampaignDefinition& def = definition();
  const auto& recs = journal_->records();
  Progress(CampaignProgress::Stage::kFinish);
  long best = -1;
  for (std::size_t i = 0; i < recs.size(); ++i) {
    if (recs[i].feasible && (best < 0 || recs[i].result.objective < recs[best].result.objective)) {
      best = static_cast<long>(i);
    }
  }
  nlohmann::json s;
  s["tool"] = std::string("hullopt ") + kVersion;
  s["command"] = command;
  s["evaluations"] = recs.size();
  s["computed_evaluations"] = static_cast<long>(recs.size()) - journal_->replayed();
  s["replayed_evaluations"] = journal_->replayed();
  s["threads"] = threads_;
  s["mpi_ranks"] = size_;
  s["seed"] = def.seed;
  s["best_objective"] = best >= 0 ? nlohmann::json(recs[best].result.objective) : nlohmann::json();
  s["best_evaluation"] = best >= 0 ? nlohmann::json(best) : nlohmann::json();
  if (const std::string method = campaign_.evaluator->ObjectiveMethod(); !method.empty())
    s["objective_method"] = method;
  const std::string warnings_line = ReportWarnings(recs, best, journal_->path(), &s);
  if (!warnings_line.empty()) Note(warnings_line);
  const std::string resolution_warning =
      best >= 0 ? CheckBestResolution(campaign_, recs[best].x, best, &s) : std::string();
  if (!resolution_warning.empty()) Note("hullopt: warning: " + resolution_warning);
  kind_.Summarise(*this, best, &s);
  s["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0_).count();
  if (options_.profile) s["profile"] = ProfileJson();
  io::WriteJson(io::OutPath(options_.out, "summary.json"), s);
  if (best >= 0) {
    char comment[200];
    std::snprintf(comment, sizeof comment, "hullopt %s: %s of %s (evaluation %ld, objective %.10g); %s",
                  command.c_str(), words_.best.c_str(), spec_.Name().c_str(), best,
                  recs[best].result.objective, words_.best_base.c_str());
    io::WriteBestYaml(io::OutPath(options_.out, "best.yaml"), campaign_.raw, campaign_.config.block,
                      def.VariableNames(), campaign_.config.start_source, recs[best].x,
                      resolution_warning.empty() ? std::string(comment)
                                                 : std::string(comment) + "\n# WARNING: " + resolution_warning);
    std::vector<std::string> campaign_warnings, active_set;
    if (!recs[best].result.warning.empty())
      campaign_warnings.push_back("best design (evaluation " + std::to_string(best) + "): " + recs[best].result.warning);
    if (!resolution_warning.empty()) campaign_warnings.push_back(resolution_warning);
    const CampaignWarnings all = CollectWarnings(recs);
    if (all.count > 0)
      campaign_warnings.push_back(std::to_string(all.count) + " of " + std::to_string(recs.size()) +
                                  " evaluations carry a warning (message column of " + journal_->path() +
                                  "); first, evaluation " + std::to_string(all.first_evaluation) + ": " +
                                  all.first_message);
    if (command == "optimize")
      active_set = ActiveSet(def, campaign_.evaluator->QuantityNames(), recs[best], campaign_.evaluator.get());
    // The figures after the numbers (summary.json, best.yaml): the report shows them.
    if (options_.plots) {
      kind_.WritePlots(*this);
      if (options_.write_report && !spec_.config_file.empty())
        options_.write_report({options_.out, command, spec_.config_file, campaign_warnings, active_set});
    }
  } else if (options_.plots) {
    kind_.WritePlots(*this);
  }
  *result = Result(true);
  result->summary = s;
  result->text = kind_.ResultText(*this, best, s);
}

nlohmann::json CampaignRunner::ProfileJson() const {
  const double n = std::max(1L, costed_);
  nlohmann::json j;
  j["evaluations_computed"] = costed_;
  j["threads"] = threads_;
  nlohmann::json ms;
  for (int s = 0; s < static_cast<int>(opt::CostStage::kCount); ++s)
    ms[opt::CostStageName(static_cast<opt::CostStage>(s))] = 1e3 * cost_.seconds[s] / n;
  // The evaluation's rest: the mass rule, the envelope, warnings and checks between the stages.
  ms["other"] = 1e3 * std::max(0.0, costed_wall_s_ - cost_.Sum()) / n;
  ms["log_io"] = 1e3 * log_s_ / n;
  j["mean_ms_per_evaluation"] = ms;
  j["mean_total_ms"] = 1e3 * (std::max(costed_wall_s_, cost_.Sum()) + log_s_) / n;
  return j;
}

std::string CampaignRunner::ProfileText() const {
  const nlohmann::json j = ProfileJson();
  const double total = j["mean_total_ms"].get<double>();
  char b[160];
  std::snprintf(b, sizeof b,
                "profile: %ld evaluations computed (%d threads); mean wall time per evaluation by stage:\n", costed_,
                threads_);
  std::string text = b;
  std::vector<std::string> stages;
  for (int s = 0; s < static_cast<int>(opt::CostStage::kCount); ++s)
    stages.push_back(opt::CostStageName(static_cast<opt::CostStage>(s)));
  stages.push_back("other");
  stages.push_back("log_io");
  for (const std::string& stage : stages) {
    const double v = j["mean_ms_per_evaluation"][stage].get<double>();
    std::snprintf(b, sizeof b, "  %-22s %10.3f ms %6.1f %%\n", stage.c_str(), v, total > 0 ? 100.0 * v / total : 0.0);
    text += b;
  }
  std::snprintf(b, sizeof b, "  %-22s %10.3f ms\n", "total", total);
  return text + b;
}

CampaignResult CampaignRunner::Result(bool complete) const {
  CampaignResult r;
  if (options_.profile) {
    r.profile = ProfileJson();
    r.profile_text = ProfileText();
  }
  r.complete = complete;
  r.command = words_.command;
  r.log_path = journal_->path();
  r.layout = journal_->layout();
  r.history = journal_->records();
  r.replayed = journal_->replayed();
  for (std::size_t i = 0; i < r.history.size(); ++i) {
    const opt::EvaluationRecord& rec = r.history[i];
    r.reported.push_back(rec.result.produced ? constraints_->ReportedValues(rec.result)
                                             : std::vector<double>(r.layout.quantities.size(), NAN));
    if (rec.feasible && (r.best < 0 || rec.result.objective < r.history[r.best].result.objective))
      r.best = static_cast<long>(i);
  }
  return r;
}

CampaignResult RunKind(CampaignKind& kind, const CampaignSpec& spec, const CampaignRunOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) throw io::InputError(error);
  CampaignRunner runner(kind, spec, options);
  runner.Start();
  try {
    kind.Run(runner);
  } catch (const EvaluationLimitReached&) {
    return runner.Result(false);
  }
  CampaignResult result;
  if (runner.rank() == 0) runner.Finish(&result);
  return result;
}

}  // namespace hullopt::campaign
