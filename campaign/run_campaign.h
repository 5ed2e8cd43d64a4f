#pragma once
// A campaign (optimize or explore) as a library call: RunCampaign(spec, options) runs it end to end in an output
// folder (the same files the command line writes: history.csv or samples.csv, summary.json, best.yaml, the
// figures and report.html), resumes from the folder's log, and returns every evaluation and the best design.
// Nothing is printed: progress and messages go to the caller's callbacks. The `hullopt optimize` and
// `hullopt explore` commands and the Python module's optimize() call it.
#include <yaml-cpp/yaml.h>

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "campaign/campaign_comm.h"
#include "io/config/campaign_config.h"
#include "io/formats/history_csv.h"
#include "optimizer/evaluation_record.h"

namespace hullopt::campaign {

/// What to run: a campaign config as a file, or as a tree of values (e.g. built from Python dicts; no YAML
/// text), read as the config file would be.
struct CampaignSpec {
  io::CampaignCommand command = io::CampaignCommand::kOptimize;
  std::string config_file;  ///< the campaign YAML; when empty, `config` is read instead
  YAML::Node config;        ///< the config's tree (a mapping), when config_file is empty
  std::string source = "<python>";  ///< the tree's name in messages and in config.resolved.yaml's header

  static CampaignSpec FromFile(io::CampaignCommand command, const std::string& file);
  static CampaignSpec FromTree(io::CampaignCommand command, const YAML::Node& config, const std::string& source);
  /// The config's name: the file, or `source`.
  const std::string& Name() const { return config_file.empty() ? source : config_file; }
};

/// Progress of the evaluations (rank 0): a start, an update per evaluation, and the end.
struct CampaignProgress {
  enum class Stage { kStart, kUpdate, kFinish };
  Stage stage = Stage::kStart;
  std::string label;  ///< the command ("optimize", "explore")
  long total = 0;     ///< expected number of evaluations (an upper bound for an optimiser)
  long done = 0;      ///< evaluations so far, of which `replayed` came from the log
  long replayed = 0;
};

/// What report.html is written from (CampaignRunOptions::write_report).
struct CampaignReportRequest {
  std::string out, command, config_file;
  std::vector<std::string> campaign_warnings;  ///< the best design's warning, the resolution check, the count
  std::vector<std::string> active_set;         ///< optimize: bounds and constraints active at the best design
};

struct CampaignRunOptions {
  std::string out;             ///< output folder (created; a folder holding this campaign's log is resumed)
  bool resume = true;          ///< false: refuse a folder that already holds a log of evaluations
  long max_evaluations = 0;    ///< > 0: stop once this call has computed this many evaluations (see RunCampaign)
  int threads = 0;             ///< OpenMP threads (0 = the OpenMP default)
  bool force = false;          ///< run past the cost-estimate thresholds (the CLI's --force)
  bool quiet = false;          ///< no progress and no messages but the cost estimate
  bool plots = true;           ///< the SVG figures and (through write_report) report.html
  int chunk = 0;               ///< explore under several processes: samples per rank and round (0 = 2 x threads)
  /// Where the evaluations' time goes: summary.json's `profile` and CampaignResult::profile_text, the mean wall
  /// time per computed evaluation of each stage of the design evaluation (opt::CostStage) and of writing its log
  /// row. Under several processes rank 0 counts its own evaluations only.
  bool profile = false;
  /// Progress of the evaluations (rank 0, unless quiet); may be empty.
  std::function<void(const CampaignProgress&)> progress;
  /// One line each: the cost estimate, notes (resuming) and warnings, as the CLI prints them on stderr
  /// (rank 0; only the cost estimate when quiet); may be empty.
  std::function<void(const std::string&)> message;
  /// Writes report.html once the numbers are written (a config file's campaign with plots); may be empty.
  std::function<void(const CampaignReportRequest&)> write_report;
  /// The processes the work is spread over; null: this one (SerialComm()).
  const CampaignComm* comm = nullptr;

  bool IsValid(std::string* error) const;
};

struct CampaignResult {
  /// false: stopped at max_evaluations before the campaign's end (no summary.json, best.yaml or figures were
  /// written; run again with resume to continue). The other fields then describe the evaluations so far.
  bool complete = false;
  std::string command;                ///< "optimize" or "explore"
  std::string log_path;               ///< history.csv or samples.csv
  io::HistoryLayout layout;           ///< the log's columns (variables, seas, constrained quantities)
  std::vector<opt::EvaluationRecord> history;  ///< every evaluation in log order (rank 0)
  std::vector<std::vector<double>> reported;   ///< per evaluation: the values of layout.quantities
  long replayed = 0;                  ///< evaluations taken from the log, not computed
  long best = -1;                     ///< the feasible evaluation of lowest objective, -1 when none
  nlohmann::json summary;             ///< summary.json as written (empty when not complete)
  std::string text;                   ///< the result lines the command line prints (empty when not complete)
  std::string sweep;                  ///< a Pareto sweep's result line (printed even when quiet); else empty
  nlohmann::json profile;             ///< with options.profile: summary.json's `profile` (also when not complete)
  std::string profile_text;           ///< with options.profile: the same as a table, one stage a line
};

/// Runs one campaign (collective over options.comm). Throws io::InputError for bad input (the config, the
/// options, a log that does not match the campaign). A config whose optimize block has `pareto:` runs the
/// Pareto sweep (a config file only; the result is its last point's, `text` holds every point's lines and
/// `sweep` the sweep's line).
///
/// max_evaluations: the call stops after the evaluation that makes it the N-th computed one (replayed ones do
/// not count); everything computed is in the log, so a later call with resume replays it and computes nothing
/// twice. With several threads, explore also finishes the samples already started, which are not logged and
/// are computed again on resume. A campaign whose last evaluation is the N-th is finished by the next call
/// (which computes nothing). One process only.
CampaignResult RunCampaign(const CampaignSpec& spec, const CampaignRunOptions& options);

}  // namespace hullopt::campaign
