#pragma once
// Memory and time of a run's strip-solver work, estimated before the work starts, so that a config inside the
// documented maxima (io/config/motion_config.cpp) that would still run for days or exhaust memory is refused
// with its numbers and the key that drives them instead of being found out hours later (docs/bad-inputs.md,
// "Cost estimate"). The model and its measured constants are in run_cost.cpp.
#include <yaml-cpp/yaml.h>

#include <string>

namespace hullopt::io {

/// What a run asks of the strip solver.
struct StripWork {
  /// time_domain_strip | strip_theory_stf (solver.method) | section_time_domain (`hullopt section`: one fixed
  /// section strip of `panels` x `bodies` panels, time-invariant operators over up to `lags` time lags)
  std::string method = "time_domain_strip";
  std::string path = "periodic";             ///< periodic | time_marching (solver.path)
  int sections = 40;                         ///< solver.sections
  int panels = 14;                           ///< solver.panels, per wetted section of one body
  int bodies = 1;                            ///< hulls side by side in a strip (1, 2, 3)
  bool cell_faces = true;                    ///< solver.stations: cell_faces has sections + 1 steps
  long frequencies = 60;                     ///< wave frequencies per sweep
  long kernels = 1;                          ///< kernel builds of the run (designs x speeds)
  long sweeps_per_kernel = 1;                ///< frequency sweeps per kernel (a calibration's Cs trials)
  int parallel = 1;                          ///< kernels held in memory at once
  std::string parallel_key;                  ///< what sets `parallel` (e.g. "--threads"), for the message
  int lags = 6000;                           ///< section_time_domain: lag horizon (its max_lags cap)
  /// Oblique seas: the headings of each sweep (`rao`'s solver.headings_deg, a campaign objective's or the
  /// polar's headings_deg); 0 for the head-sea path.
  int headings = 0;
  /// The config key or option that sets `kernels` ("" for one design), named when the count drives a refusal.
  std::string count_key;
};

struct RunCost {
  double kernel_seconds = 0.0;  ///< [s] one kernel build (CPU time of one core)
  double sweep_seconds = 0.0;   ///< [s] one frequency sweep on a built kernel
  double kernel_bytes = 0.0;    ///< [B] one kernel while it is built (operators, responses, force rows)
  double seconds = 0.0;         ///< [s] the whole run: kernels x (kernel + sweeps x sweep)
  double bytes = 0.0;           ///< [B] peak: parallel x kernel_bytes
};

/// Refusal thresholds (docs/bad-inputs.md): beyond them a run needs --force.
constexpr double kCostLimitBytes = 8.0 * 1024 * 1024 * 1024;  // 8 GiB: a laptop's or a shared node's share
constexpr double kCostLimitSeconds = 3600.0;                   // 1 h: beyond it, state the intent

/// The estimate (one core; a multi-core run is faster by at most its core count).
RunCost EstimateRunCost(const StripWork& work);

/// The strip settings of a resolved config (solver.* and hull.*, as recorded in config.resolved.yaml with
/// every default filled in); counts (kernels, sweeps, parallel, count_key) are left at one design. `frequencies`
/// is the count the config's solver.frequencies gives, or default_frequencies when it has none.
StripWork StripWorkFromResolved(const YAML::Node& resolved, long default_frequencies);

/// One line (no prefix, no newline): the work and its estimate, e.g. "cost estimate: 1 kernel of 41 steps x 28
/// panels, 60 frequencies: about 1.2 s, 35 MiB".
std::string DescribeRunCost(const StripWork& work, const RunCost& cost);

/// "" when the estimate is within both thresholds; otherwise the refusal (no prefix): which limit, the
/// numbers, and the key that drives it (the design count, or solver.sections and solver.panels, or
/// solver.frequencies), with "give --force to run it anyway".
std::string RunCostRefusal(const StripWork& work, const RunCost& cost);

/// The cost check of a run: throws io::InputError ("<command>: <refusal>") when the estimate is beyond a
/// threshold and `force` is false; returns the line to show (no newline: "hullopt: <command>: cost estimate:
/// ...", with a note when running past a threshold because of force), or "" for a run that finishes within a
/// minute and fits in 1 GiB (nothing worth a line).
std::string CheckRunCostLine(const std::string& command, const StripWork& work, bool force);

}  // namespace hullopt::io
