#pragma once
// Subcommands of the hullopt executable. Each Add*Command registers its subcommand on the app; its callback
// throws io::InputError for bad input (printed by main as one line, exit code 1).
#include <CLI/CLI.hpp>

namespace hullopt::app {
void AddHullCommand(CLI::App& app);
void AddSectionCommand(CLI::App& app);
void AddRaoCommand(CLI::App& app);
void AddEvaluateCommand(CLI::App& app);
void AddDesignCommand(CLI::App& app);
void AddOptimizeCommand(CLI::App& app);
void AddExploreCommand(CLI::App& app);
void AddCalibrateCommand(CLI::App& app);
void AddResistanceCommand(CLI::App& app);
void AddCoefficientsCommand(CLI::App& app);
/// All of the above, in the order of `hullopt --help` (the executable and the Python module's run()).
void AddAllCommands(CLI::App& app);
}  // namespace hullopt::app
