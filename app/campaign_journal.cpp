#include "app/campaign_journal.h"

#include <filesystem>

#include "app/mpi_context.h"
#include "app/output_dir.h"
#include "io/campaign_outputs.h"
#include "io/input_error.h"
#include "io/yaml_difference.h"

namespace hullopt::app {

CampaignJournal::CampaignJournal(const std::string& dir, const std::string& file, io::HistoryLayout layout,
                                 const std::string& config_hash, const YAML::Node& resolved,
                                 const opt::ConstraintSet& constraints, std::size_t quantities)
    : dir_(dir),
      path_(OutPath(dir, file)),
      hash_path_(OutPath(dir, file + ".config_hash")),
      config_hash_(config_hash),
      layout_(std::move(layout)),
      constraints_(constraints),
      quantities_(quantities) {
  // Rank 0 reads; everyone parses the same text, so every rank reaches the same verdict.
  std::string text, stored_hash;
  if (MpiRank() == 0) {
    text = io::ReadTextFile(path_);
    stored_hash = io::ReadTextFile(hash_path_);
  }
  text = MpiBroadcast(text);
  stored_hash = MpiBroadcast(stored_hash);
  const io::HistoryFile log = io::ParseHistory(text, path_, layout_);
  if (log.exists) {
    while (!stored_hash.empty() && (stored_hash.back() == '\n' || stored_hash.back() == ' '))
      stored_hash.pop_back();
    if (stored_hash != config_hash_) {
      // Say what changed: the earlier run's config.resolved.yaml against this one (a newer hullopt may also
      // have added keys with their defaults).
      std::string earlier = MpiRank() == 0 ? io::ReadTextFile(OutPath(dir, "config.resolved.yaml")) : "";
      earlier = MpiBroadcast(earlier);
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
    index_[{row.record.run, row.record.step}] = logged_.size();
    logged_.push_back(FromRow(row));
  }
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

void CampaignJournal::StartWriting() {
  if (MpiRank() != 0) return;
  io::WriteTextFileDurably(hash_path_, config_hash_ + "\n");
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

}  // namespace hullopt::app
