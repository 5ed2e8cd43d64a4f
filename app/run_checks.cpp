#include "app/run_checks.h"

#include <CLI/CLI.hpp>
#include <cstdio>

#include "app/mpi_context.h"
#include "io/formats/input_error.h"

namespace hullopt::app {
namespace {

bool force_given = false;

}  // namespace

void AddForceOption(CLI::App* command) {
  command->add_flag("--force", force_given,
                    "run even when the estimated memory (> 8 GiB) or time (> 1 h) is beyond the limits "
                    "(docs/bad-inputs.md)");
}

void ResetForceOption() { force_given = false; }

void CheckRunCost(const std::string& command, const io::StripWork& work) {
  const io::RunCost cost = io::EstimateRunCost(work);
  const std::string refusal = io::RunCostRefusal(work, cost);
  if (!refusal.empty() && !force_given) throw io::InputError(command + ": " + refusal);
  // Runs that finish within a minute and fit in 1 GiB are not worth a line: stderr then holds only warnings.
  constexpr double kQuietSeconds = 60.0, kQuietBytes = 1024.0 * 1024.0 * 1024.0;
  if (MpiRank() != 0 || (refusal.empty() && cost.seconds < kQuietSeconds && cost.bytes < kQuietBytes)) return;
  std::fprintf(stderr, "hullopt: %s: %s%s\n", command.c_str(), io::DescribeRunCost(work, cost).c_str(),
               refusal.empty() ? "" : " (beyond the limits; running because of --force)");
}

void CheckCampaignCost(const std::string& command, const YAML::Node& resolved, const std::string& block,
                       long evaluations, const std::string& count_key, int parallel) {
  const YAML::Node objective = resolved[block] ? resolved[block]["objective"] : YAML::Node();
  if (objective && objective.IsMap() && objective["analytic"]) return;
  // 60: the sea-evaluation grid when solver.frequencies is absent (app/design_case.h EvaluationFrequencies).
  io::StripWork work = io::StripWorkFromResolved(resolved, 60);
  work.kernels = evaluations;
  work.count_key = count_key;
  work.parallel = parallel;
  work.parallel_key = "--threads";
  CheckRunCost(command, work);
}

}  // namespace hullopt::app
