#include "campaign/campaign_journal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "io/formats/atomic_file.h"
#include "io/config/campaign_outputs.h"
#include "io/config/output_folder.h"
#include "io/formats/input_error.h"
#include "io/config/yaml_difference.h"

namespace hullopt::campaign {

CampaignJournal::CampaignJournal(const CampaignComm& comm, const std::string& dir, const std::string& file, io::HistoryLayout layout,
                                 const std::string& config_hash, const YAML::Node& resolved,
                                 const opt::ConstraintSet& constraints, std::size_t quantities)
    : comm_(comm),
      dir_(dir),
      path_(io::OutPath(dir, file)),
      hash_path_(io::OutPath(dir, file + ".config_hash")),
      config_hash_(config_hash),
      layout_(std::move(layout)),
      constraints_(constraints),
      quantities_(quantities) {
  // Rank 0 reads; everyone parses the same text, so every rank reaches the same verdict.
  std::string text, stored_hash;
  if (comm_.Rank() == 0) {
    text = io::ReadTextFile(path_);
    stored_hash = io::ReadTextFile(hash_path_);
  }
  text = comm_.Broadcast(text);
  stored_hash = comm_.Broadcast(stored_hash);
  const io::HistoryFile log = io::ParseHistory(text, path_, layout_);
  if (log.exists) {
    while (!stored_hash.empty() && (stored_hash.back() == '\n' || stored_hash.back() == ' '))
      stored_hash.pop_back();
    if (stored_hash != config_hash_) {
      // Say what changed: the earlier run's config.resolved.yaml against this one (a newer hullopt may also
      // have added keys with their defaults).
      std::string earlier = comm_.Rank() == 0 ? io::ReadTextFile(io::OutPath(dir, "config.resolved.yaml")) : "";
      earlier = comm_.Broadcast(earlier);
      std::string change;
      try {
        if (!earlier.empty()) change = io::FirstYamlDifference(YAML::Load(earlier), resolved);
      } catch (const YAML::Exception&) {
        change.clear();
      }
      throw io::InputError(path_ +
                           ": this output folder holds a campaign run with a different config (config "
                           "hash " +
                           (stored_hash.empty() ? std::string("missing") : stored_hash) + ", now " +
                           config_hash_ + (change.empty() ? "" : "; first difference: " + change) +
                           "); refusing to resume: use another --out folder, or delete " + path_ +
                           " to start over");
    }
  }
  for (const auto& row : log.rows) {
    index_.emplace(std::make_pair(row.record.run, row.record.step), logged_.size());
    logged_.push_back(FromRow(row));
  }
  rows_ = log.rows;
  valid_bytes_ = log.exists ? log.valid_bytes : 0;
  truncated_tail_ = log.truncated_tail;
}

CampaignJournal::~CampaignJournal() = default;

opt::EvaluationRecord CampaignJournal::FromRow(const io::HistoryRow& row) const {
  opt::EvaluationRecord rec = row.record;
  if (rec.result.produced)
    rec.result.quantities = constraints_.QuantitiesFromReported(row.reported, quantities_);
  return rec;
}

void CampaignJournal::Verify(opt::Evaluator& evaluator, const opt::CampaignDefinition& def) const {
  std::string problem = comm_.Rank() == 0 ? FirstProblem(evaluator, def) : std::string();
  problem = comm_.Broadcast(problem);
  if (!problem.empty())
    throw io::InputError(problem + " (the log was edited or damaged: it cannot be replayed; delete " + path_ +
                         " to start the campaign over)");
}

std::string CampaignJournal::FirstProblem(opt::Evaluator& evaluator, const opt::CampaignDefinition& def) const {
  const auto lower = def.LowerBounds(), upper = def.UpperBounds();
  auto where = [&](std::size_t i, const std::string& column) {
    return path_ + ":" + std::to_string(i + 2) + ": column '" + column + "'";
  };
  auto num = [](double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return std::string(buf);
  };
  auto differs = [](double logged, double now) {
    return !(std::fabs(logged - now) <= kSpotRelTol * std::max({std::fabs(logged), std::fabs(now), 1.0}));
  };
  std::set<std::pair<int, int>> seen;
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const opt::EvaluationRecord& rec = logged_[i];
    for (std::size_t j = 0; j < rec.x.size(); ++j) {
      if (rec.x[j] < lower[j] || rec.x[j] > upper[j])
        return where(i, layout_.variables[j]) + " = " + num(rec.x[j]) + ": outside the variable's bounds [" +
               num(lower[j]) + ", " + num(upper[j]) + "]";
    }
    if (!seen.insert({rec.run, rec.step}).second)
      return where(i, "step") + ": run " + std::to_string(rec.run) + " step " + std::to_string(rec.step) +
             " is logged twice";
    if (rec.result.produced) {
      const double implied = evaluator.ObjectiveImplied(rec.x, rec.result.sea_values);
      if (std::isfinite(implied) && differs(rec.result.objective, implied))
        return where(i, "objective") + " = " + num(rec.result.objective) + ": the row's design " +
               (rec.result.sea_values.empty() ? "variables give " : "and per-sea values give ") + num(implied);
    }
    const bool feasible = constraints_.Feasible(rec.x, rec.result, def.feasibility_tol);
    if (feasible != rec.feasible)
      return where(i, "feasible") + " = " + (rec.feasible ? "1" : "0") + ": the row's own values give " +
             (feasible ? "1" : "0") + " under the campaign's constraints";
  }
  // Spot check: recompute a few rows and compare every result column.
  std::vector<std::size_t> spots;
  const std::size_t n = rows_.size();
  for (int k = 0; k < kSpotRows && n > 0; ++k) spots.push_back(k * (n - 1) / (kSpotRows - 1));
  // The rows a resumed campaign would report as its best: whatever the summary and report name as the best
  // design was recomputed, so a row edited to look better than it is (objective and per-sea values changed
  // consistently, which the implied-objective check cannot see) is found before it is reported.
  std::vector<std::size_t> ranked;
  for (std::size_t i = 0; i < n; ++i)
    if (logged_[i].feasible && logged_[i].result.produced) ranked.push_back(i);
  const std::size_t best_count = std::min<std::size_t>(kBestRows, ranked.size());
  std::partial_sort(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(best_count), ranked.end(),
                    [&](std::size_t a, std::size_t b) {
                      return logged_[a].result.objective < logged_[b].result.objective;
                    });
  spots.insert(spots.end(), ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(best_count));
  std::sort(spots.begin(), spots.end());
  spots.erase(std::unique(spots.begin(), spots.end()), spots.end());
  for (const std::size_t i : spots) {
    const io::HistoryRow& row = rows_[i];
    opt::EvaluationRecord now = row.record;
    now.result = opt::EvaluateSafely(evaluator, row.record.x);
    now.feasible = constraints_.Feasible(now.x, now.result, def.feasibility_tol);
    // Through the row format, so that the message is compared as it is logged (commas replaced).
    std::string line = io::FormatHistoryRow(row.evaluation, now, constraints_.ReportedValues(now.result), layout_);
    line.pop_back();  // the newline
    const io::HistoryRow again = io::ParseHistoryRow(line, layout_, "recomputed row");
    char because[96];
    std::snprintf(because, sizeof because, " (recomputed now: spot check of the log, relative tolerance %g)",
                  kSpotRelTol);
    const auto& a = row.record.result;
    const auto& b = again.record.result;
    if (a.produced != b.produced || a.error != b.error || a.warning != b.warning) {
      auto shown = [](const opt::EvalResult& r) {
        return r.produced ? (r.warning.empty() ? std::string() : io::kWarningPrefix + r.warning) : r.error;
      };
      return where(i, "message") + ": logged '" + shown(a) + "', the design gives '" + shown(b) + "'" + because;
    }
    if (!a.produced) continue;
    if (differs(a.objective, b.objective))
      return where(i, "objective") + " = " + num(a.objective) + ": the design gives " + num(b.objective) + because;
    for (std::size_t j = 0; j < a.sea_values.size(); ++j)
      if (differs(a.sea_values[j], b.sea_values[j]))
        return where(i, layout_.seas[j]) + " = " + num(a.sea_values[j]) + ": the design gives " +
               num(b.sea_values[j]) + because;
    for (std::size_t j = 0; j < row.reported.size(); ++j)
      if (differs(row.reported[j], again.reported[j]))
        return where(i, layout_.quantities[j]) + " = " + num(row.reported[j]) + ": the design gives " +
               num(again.reported[j]) + because;
  }
  return "";
}

void CampaignJournal::StartWriting() {
  if (comm_.Rank() != 0) return;
  io::WriteFileAtomically(hash_path_, config_hash_ + "\n");
  appender_ = std::make_unique<io::HistoryAppender>(path_, layout_, valid_bytes_);
}

opt::ReplayLookup CampaignJournal::Replay() const {
  return [this](int run, int step) -> const opt::EvaluationRecord* {
    auto it = index_.find({run, step});
    return it == index_.end() ? nullptr : &logged_[it->second];
  };
}

long CampaignJournal::Add(const opt::EvaluationRecord& rec) {
  const long n = static_cast<long>(records_.size());
  if (n >= logged()) {
    if (appender_)
      appender_->Append(io::FormatHistoryRow(n, rec, constraints_.ReportedValues(rec.result), layout_));
  } else {
    ++replayed_;
  }
  records_.push_back(rec);
  return n;
}

std::string CampaignJournal::Serialise(const opt::EvaluationRecord& rec) const {
  return io::FormatHistoryRow(0, rec, constraints_.ReportedValues(rec.result), layout_);
}

opt::EvaluationRecord CampaignJournal::Deserialise(const std::string& line) const {
  opt::EvaluationRecord rec = FromRow(io::ParseHistoryRow(line, layout_, "MPI transfer"));
  return rec;
}

}  // namespace hullopt::campaign
