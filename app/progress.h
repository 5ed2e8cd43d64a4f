#pragma once
// Progress report of a long campaign on stderr: a redrawn bar with rate and ETA when stderr is a terminal,
// plain lines (every 10 % or 30 s) when it is a file or pipe (batch jobs, CI logs).
#include <chrono>
#include <cstdio>
#include <string>

namespace hullopt::app {

class Progress {
 public:
  /// total: expected number of evaluations (an upper bound for optimisation). enabled = false: silent
  /// (MPI ranks other than 0, --quiet).
  Progress(std::string label, long total, bool enabled = true);
  /// done: evaluations finished so far, of which `replayed` came from the log (they do not count for the
  /// rate).
  void Update(long done, long replayed);
  /// Ends the bar with a final line.
  void Finish(long done, long replayed);

 private:
  std::string Line(long done, long replayed) const;
  std::string label_;
  long total_;
  bool enabled_;
  bool tty_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  int last_decile_ = -1;
};

/// "1h02m", "3m05s", "12s".
std::string FormatDuration(double seconds);

}  // namespace hullopt::app
