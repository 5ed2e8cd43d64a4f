#pragma once
#include <yaml-cpp/yaml.h>
// The durable log of a campaign (history.csv or samples.csv) and its resume logic: on start, rows already in
// the file are read back (an incomplete last line from a kill is discarded) and offered for replay; rows are
// appended and fsync'd one by one as evaluations complete; a log made with a different config is refused.
// With several processes (CampaignComm), rank 0 reads and writes the file; the logged rows are broadcast so
// every rank can replay.
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "campaign/campaign_comm.h"
#include "io/formats/history_csv.h"
#include "optimizer/campaign.h"
#include "optimizer/constraint_set.h"
#include "optimizer/evaluation_record.h"
#include "optimizer/evaluator.h"

namespace hullopt::campaign {

class CampaignJournal {
 public:
  /// Collective. Reads DIR/file and DIR/file.config_hash on rank 0 and shares them. Throws io::InputError if
  /// the log exists but was made with a different config (hash of config.resolved.yaml; the message names the
  /// first key where DIR/config.resolved.yaml of the earlier run differs from `resolved`), or is damaged.
  CampaignJournal(const CampaignComm& comm, const std::string& dir, const std::string& file, io::HistoryLayout layout,
                  const std::string& config_hash, const YAML::Node& resolved,
                  const opt::ConstraintSet& constraints, std::size_t quantities);
  ~CampaignJournal();

  /// Collective. Checks every logged row against what the campaign implies before it is replayed: design
  /// variables within their bounds, (run, step) unique, the objective equal to what the row's variables and
  /// per-sea values imply (Evaluator::ObjectiveImplied, where the evaluator can say), `feasible` equal to the
  /// constraints applied to the row's own values; and recomputes a spot sample of rows (kSpotRows: the first, the last and evenly spaced
  /// ones between, and the kBestRows best feasible rows) with the evaluator, whose objective, per-sea values, constrained quantities, status and
  /// message must agree within kSpotRelTol. (Finite numbers and the refused/evaluated pattern are checked when
  /// the file is read.) Throws io::InputError naming the file, line and column of the first mismatch.
  void Verify(opt::Evaluator& evaluator, const opt::CampaignDefinition& def) const;

  /// Rows recomputed by Verify: the first, the last and evenly spaced ones between (fewer if the log is short).
  static constexpr int kSpotRows = 4;
  /// Verify also recomputes the kBestRows feasible rows of lowest objective (the best design a resumed campaign
  /// reports and its runners-up): an optimize log replays only when its later steps follow from the logged
  /// results, but an explore log's samples do not depend on each other, so a row edited consistently would
  /// otherwise be reported as the best. Three: the best and two runners-up, each one evaluation on resume.
  static constexpr int kBestRows = 3;
  /// Relative tolerance of the spot check and of the implied objective (plus the same absolute tolerance for values near 0). Evaluators are
  /// deterministic bit for bit for one build (opt::Evaluator's contract; tests/cli/campaign_parallel.sh checks
  /// it across thread counts), so an unchanged row agrees exactly with the binary that wrote it; 1e-9 leaves
  /// room for a rebuild with different floating-point contraction or vectorisation (which changes sums of
  /// the strip kernel by ~1e-13 relative) and for nothing a hand edit or damage would produce.
  static constexpr double kSpotRelTol = 1e-9;

  /// Rank 0: opens the file for appending (dropping an incomplete last line, writing the header if new) and
  /// records the config hash. Call after the output folder is prepared, before the first evaluation.
  void StartWriting();

  /// Replay source for the optimiser / sampler: the logged record of (run, step) or nullptr.
  opt::ReplayLookup Replay() const;
  long logged() const { return static_cast<long>(logged_.size()); }
  bool truncated_tail() const { return truncated_tail_; }

  /// Rank 0: takes the next evaluation in sequence order; appends it unless it is already in the file.
  /// Returns its evaluation number.
  long Add(const opt::EvaluationRecord& rec);
  /// All records taken by Add, in order (rank 0).
  const std::vector<opt::EvaluationRecord>& records() const { return records_; }
  long replayed() const { return replayed_; }

  /// Transport between MPI ranks: a record as one history row (evaluation number 0) and back.
  std::string Serialise(const opt::EvaluationRecord& rec) const;
  opt::EvaluationRecord Deserialise(const std::string& line) const;

  const io::HistoryLayout& layout() const { return layout_; }
  const std::string& path() const { return path_; }

 private:
  opt::EvaluationRecord FromRow(const io::HistoryRow& row) const;
  std::string FirstProblem(opt::Evaluator& evaluator, const opt::CampaignDefinition& def) const;

  const CampaignComm& comm_;
  std::string dir_, path_, hash_path_, config_hash_;
  io::HistoryLayout layout_;
  const opt::ConstraintSet& constraints_;
  std::size_t quantities_;
  std::vector<opt::EvaluationRecord> logged_;
  std::vector<io::HistoryRow> rows_;  ///< the logged rows as read (for Verify)
  std::map<std::pair<int, int>, std::size_t> index_;
  std::size_t valid_bytes_ = 0;
  bool truncated_tail_ = false;
  std::unique_ptr<io::HistoryAppender> appender_;
  std::vector<opt::EvaluationRecord> records_;
  long replayed_ = 0;
};

}  // namespace hullopt::campaign
