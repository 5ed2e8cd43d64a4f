#pragma once
// Checks a command makes once its input is read and before its work starts: the estimated cost of its
// strip-solver work (io/config/run_cost.h; refused beyond the documented thresholds unless --force) and,
// through CheckOutputDirConfig, that its output folder holds no other command's or config's results.
#include <string>

#include "app/cli_app.h"
#include "io/config/run_cost.h"

namespace hullopt::app {

/// Adds `--force` (run past the cost-estimate thresholds) to a subcommand. Every command that runs the strip
/// solver has it (AddAllCommands).
void AddForceOption(CLI::App* command);
/// Clears --force (a new command line is about to be parsed, e.g. by the Python module's run()).
void ResetForceOption();

/// Prints the estimate as one line on stderr ("hullopt: <command>: cost estimate: ...", MPI rank 0 only) and
/// throws io::InputError naming the limit, the numbers and the key that drives them when the estimate is beyond
/// io::kCostLimitBytes or io::kCostLimitSeconds and --force was not given (with --force: a note instead).
void CheckRunCost(const std::string& command, const io::StripWork& work);

/// Whether --force was given on this command line (the campaigns take it as CampaignRunOptions::force).
bool ForceGiven();

}  // namespace hullopt::app
