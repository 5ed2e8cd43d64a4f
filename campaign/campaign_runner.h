#pragma once
// The one runner of the campaigns (RunCampaign, campaign/run_campaign.h; `hullopt optimize`, `hullopt explore`):
// it loads and checks the campaign config, resolves threads and checks the cost, opens the durable log
// (history.csv, samples.csv) and verifies it for resume, prepares the output folder, reports progress, splits
// the work over processes (CampaignComm) and gathers the records on rank 0 in order, and at the end writes what
// every campaign writes: summary.json (the common keys, the warnings, the resolution check of the best design),
// best.yaml and (through the caller's writer) report.html.
//
// What differs between campaigns is a CampaignKind: how the evaluations are produced (a multistart optimiser,
// a sample of the design box), what the kind adds to the summary, its plots and its result lines. A new
// campaign type is one more CampaignKind (docs/developer-guide.md).
#include <nlohmann/json.hpp>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "campaign/campaign_journal.h"
#include "campaign/campaign_setup.h"
#include "campaign/run_campaign.h"
#include "io/config/campaign_config.h"
#include "io/formats/input_error.h"
#include "optimizer/constraint_set.h"
#include "optimizer/evaluation_record.h"

namespace hullopt::campaign {

/// The size of a campaign, for the cost check and the progress bar.
struct CampaignSize {
  long evaluations = 0;   ///< expected number of evaluations (an upper bound for an optimiser)
  std::string count_key;  ///< the config key(s) that set it, named by the cost check
  int parallel = 1;       ///< evaluations that run at once (threads over designs)
};

class CampaignRunner;

/// One kind of campaign. The runner calls, in this order: Size, Accept (collective), Run (collective), and on
/// rank 0 after the evaluations Summarise, WritePlots, ResultText.
class CampaignKind {
 public:
  virtual ~CampaignKind() = default;
  /// The names and words of the kind's files and messages.
  struct Words {
    std::string command;   ///< "optimize": progress label, messages, summary "command", report title
    std::string log_file;  ///< the log in the output folder ("history.csv")
    std::string resumed;   ///< what a resumed run says it replays ("evaluations")
    std::string sequence;  ///< what the log must match to be resumed ("sequence")
    std::string best;      ///< best.yaml's comment: what the best is ("best design") ...
    std::string best_base; ///< ... and what the file holds ("base config with the best variable values")
  };
  virtual Words Wording() const = 0;
  /// Which campaign block the config is read as.
  virtual io::CampaignCommand ConfigCommand() const = 0;
  /// Checks the kind's own command-line options (throws io::InputError), once the config is loaded.
  virtual void CheckOptions() const {}
  virtual CampaignSize Size(const LoadedCampaign& campaign, int threads) const = 0;
  /// Logged evaluations a resumed run replays (for its message).
  virtual long Resumed(const CampaignRunner& runner) const;
  /// Collective, before anything is written: evaluations that decide whether the campaign may start. Returns
  /// "" or, on rank 0, the one-line reason it may not (the runner throws it on every rank).
  virtual std::string Accept(CampaignRunner& runner);
  /// Collective: produces every evaluation, in sequence order, through runner.Add (rank 0) or runner.Split.
  virtual void Run(CampaignRunner& runner) = 0;
  /// Rank 0: the kind's keys of summary.json (the runner has set the common ones; best is -1 without a
  /// feasible design).
  virtual void Summarise(const CampaignRunner& runner, long best, nlohmann::json* summary) = 0;
  virtual void WritePlots(const CampaignRunner& runner) const = 0;
  /// Rank 0: the result lines (what the command line prints on stdout), each ending in a newline.
  virtual std::string ResultText(const CampaignRunner& runner, long best, const nlohmann::json& summary) const = 0;
};

/// The shared state and services of a running campaign, handed to its CampaignKind.
class CampaignRunner {
 public:
  const CampaignRunOptions& options() const { return options_; }
  /// The config's name in messages (its file, or the name of a config given as a tree).
  const std::string& config_name() const { return spec_.Name(); }
  const LoadedCampaign& campaign() const { return campaign_; }
  const opt::CampaignDefinition& definition() const { return campaign_.config.definition; }
  opt::Evaluator& evaluator() const { return *campaign_.evaluator; }
  const opt::ConstraintSet& constraints() const { return *constraints_; }
  const CampaignJournal& journal() const { return *journal_; }
  int threads() const { return threads_; }
  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Rank 0, unless quiet: one line for the caller's message callback (notes, warnings).
  void Note(const std::string& line) const;
  /// Rank 0: takes the next evaluation in sequence order (logged unless it is replayed) and updates progress.
  void Add(const opt::EvaluationRecord& rec);
  /// The io::InputError for a log whose rows do not match what the campaign asks for now.
  io::InputError ResumeError(const opt::ReplayMismatch& e) const;

  /// One unit of work on its rank: evaluate, handing each record to sink in sequence order; returns what the
  /// unit reports (a JSON object, gathered on rank 0).
  using UnitWork = std::function<nlohmann::json(int unit, const opt::RecordSink& sink)>;
  /// Collective: units 0..units-1 in rounds of size(), unit round·size + rank on each rank. With one
  /// process the records go straight to Add; with several they travel as log rows and rank 0 adds them after
  /// each round in unit order. Returns the units' reports on rank 0, in unit order (empty on other ranks).
  /// One process with several threads (and a thread-safe evaluator) runs the units on the threads, one unit
  /// per thread at a time (the evaluations inside a unit then run on that thread), and adds the records in
  /// unit order as above: the log is the one of one thread. A unit that finishes before the units ahead of
  /// it keeps its records in memory until they finish; a kill loses those (they are recomputed on resume).
  /// `work` must then be safe to call concurrently for different units.
  std::vector<nlohmann::json> Split(int units, const UnitWork& work);

 private:
  friend CampaignResult RunKind(CampaignKind& kind, const CampaignSpec& spec, const CampaignRunOptions& options);
  CampaignRunner(CampaignKind& kind, const CampaignSpec& spec, const CampaignRunOptions& options);
  void Start();
  void Finish(CampaignResult* result);
  void Progress(CampaignProgress::Stage stage) const;
  std::vector<nlohmann::json> SplitOverThreads(int units, const UnitWork& work);
  CampaignResult Result(bool complete) const;

  CampaignKind& kind_;
  CampaignKind::Words words_;
  CampaignSpec spec_;
  CampaignRunOptions options_;
  const CampaignComm& comm_;
  long total_ = 0;  ///< expected evaluations (progress)
  std::chrono::steady_clock::time_point wall0_;
  LoadedCampaign campaign_;
  int threads_ = 1, rank_ = 0, size_ = 1;
  std::unique_ptr<opt::ConstraintSet> constraints_;
  std::unique_ptr<CampaignJournal> journal_;
  // --profile: the stage times of the evaluations computed here, their wall times and the log's writes.
  opt::EvalCost cost_;
  long costed_ = 0;
  double costed_wall_s_ = 0.0, log_s_ = 0.0;
  nlohmann::json ProfileJson() const;
  std::string ProfileText() const;
};

/// Runs one campaign of the given kind end to end (collective). Throws io::InputError for bad input.
CampaignResult RunKind(CampaignKind& kind, const CampaignSpec& spec, const CampaignRunOptions& options);

/// Thrown by CampaignRunner::Add once max_evaluations are computed; RunKind returns the incomplete result.
struct EvaluationLimitReached {};

/// JSON object {names[i]: values[i]}.
nlohmann::json NamedValues(const std::vector<std::string>& names, const std::vector<double>& values);

}  // namespace hullopt::campaign
