#pragma once
// history.csv (optimize) and samples.csv (explore): one row per evaluation, appended and fsync'd as each
// evaluation completes, read back on restart to resume a campaign without recomputing anything.
//
// Columns (docs/file-formats.md; the first ones are a contract):
//   evaluation, <design variables by name>, objective, feasible, <per-sea columns>, <constrained quantities>,
//   wall_time_s, run, step, message
// Numbers are written with %.17g so that they read back bit-identical. A design the generator refused has
// objective/sea/quantity values "nan", feasible 0 and the refusal in `message` (commas replaced by ';'). An
// evaluated design with a warning (opt::EvalResult::warning, e.g. near-singular strip sections) has its numbers
// and "warning: ..." in `message`; an evaluated design without one has `message` empty.
// run is the multistart run (-1 for the baseline evaluation; 0 for exploration samples), step the position
// in that run's sequence.
#include <cstddef>
#include <string>
#include <vector>

#include "optimizer/evaluation_record.h"

namespace hullopt::io {

/// Prefix of a produced design's warning in the `message` column.
inline const std::string kWarningPrefix = "warning: ";

struct HistoryLayout {
  std::vector<std::string> variables;
  std::vector<std::string> seas;        ///< Evaluator::SeaNames()
  std::vector<std::string> quantities;  ///< ConstraintSet::ReportedQuantities()
  std::string Header() const;           ///< without the trailing newline
};

/// One row (with trailing newline). `reported` are the values of layout.quantities.
std::string FormatHistoryRow(long evaluation, const opt::EvaluationRecord& rec,
                             const std::vector<double>& reported, const HistoryLayout& layout);

struct HistoryRow {
  long evaluation = 0;
  opt::EvaluationRecord record;  ///< result.quantities left empty: see `reported`
  std::vector<double> reported;  ///< values of layout.quantities
};

struct HistoryFile {
  bool exists = false;           ///< file present with at least a complete header line
  std::vector<HistoryRow> rows;  ///< complete rows, in file order
  std::size_t valid_bytes = 0;   ///< length of the header + complete rows
  bool truncated_tail = false;   ///< an incomplete last line (killed mid-write) was found and discarded
};

/// Reads a history/samples file written with `layout`. A missing or empty file gives exists = false. Throws
/// InputError (naming file and line) if the header differs from the layout, a complete row is malformed, or
/// the evaluation numbers are not 0, 1, 2, ...
HistoryFile ReadHistory(const std::string& path, const HistoryLayout& layout);

/// Parses one complete row (without its newline). `where` prefixes error messages ("file:line").
HistoryRow ParseHistoryRow(const std::string& line, const HistoryLayout& layout, const std::string& where);

/// The layout a history/samples file declares in its header line, for a reader that does not know the campaign
/// that wrote it (the Pareto sweep's summary). The header does not tell the per-sea columns from the
/// constrained quantities, so all the columns between `feasible` and `wall_time_s` come back as `quantities`
/// (`seas` empty); ReadHistory with it then puts their values in HistoryRow::reported. Throws InputError
/// (naming the file) if the file is missing or its header lacks the fixed columns.
HistoryLayout ReadHistoryLayout(const std::string& path);

/// ReadHistory on text already in memory (e.g. broadcast from MPI rank 0); path is used in messages.
HistoryFile ParseHistory(const std::string& text, const std::string& path, const HistoryLayout& layout);

/// Appends rows durably: each Append is one write() of a whole line followed by fsync, so a SIGKILL leaves at
/// most one incomplete last line (which ReadHistory discards).
class HistoryAppender {
 public:
  /// Opens path, truncating it to keep_bytes (the valid part read by ReadHistory; 0 = start afresh) and
  /// writing the header if keep_bytes is 0. Throws InputError if the file cannot be written.
  HistoryAppender(const std::string& path, const HistoryLayout& layout, std::size_t keep_bytes);
  ~HistoryAppender();
  HistoryAppender(const HistoryAppender&) = delete;
  HistoryAppender& operator=(const HistoryAppender&) = delete;
  void Append(const std::string& line);

 private:
  void WriteAll(const std::string& text);
  std::string path_;
  int fd_ = -1;
};

}  // namespace hullopt::io
