#include "app/run_checks.h"

#include <CLI/CLI.hpp>
#include <cstdio>

#include "app/mpi_context.h"

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
  const std::string line = io::CheckRunCostLine(command, work, force_given);
  if (MpiRank() == 0 && !line.empty()) std::fprintf(stderr, "%s\n", line.c_str());
}

bool ForceGiven() { return force_given; }

}  // namespace hullopt::app
