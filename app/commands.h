#pragma once
// Subcommands of the hullopt executable. Each Add*Command registers its subcommand on the app; its callback
// throws io::InputError for bad input (printed by main as one line, exit code 1).
#include <functional>
#include <string>

#include "app/cli_app.h"

namespace hullopt::app {

/// What `hullopt NAME CONFIG --out DIR` shows in --help.
struct CommandText {
  const char* name;
  const char* description;
  const char* config_help;
  const char* config_name = "config";       ///< the positional argument's name
  const char* out_help = "output folder";
  const char* default_out = nullptr;        ///< --out when it is not given (nullptr: --out is required)
};
/// Registers `hullopt NAME CONFIG --out DIR`; its callback holds the output folder's lock (OutputFolderGuard)
/// while run(config, out) runs. Returns the subcommand, for the command's further options.
CLI::App* AddConfigCommand(CLI::App& app, const CommandText& text,
                           std::function<void(const std::string& config, const std::string& out)> run);

void AddHullCommand(CLI::App& app);
void AddSectionCommand(CLI::App& app);
void AddRaoCommand(CLI::App& app);
void AddEvaluateCommand(CLI::App& app);
void AddDesignCommand(CLI::App& app);
void AddOptimizeCommand(CLI::App& app);
void AddExploreCommand(CLI::App& app);
/// `hullopt calibrate`: registers the command; its run is RunCalibrate (app/calibrate_command.h).
void AddCalibrateCommand(CLI::App& app);
void AddResistanceCommand(CLI::App& app);
void AddCoefficientsCommand(CLI::App& app);
/// All of the above, in the order of `hullopt --help` (the executable and the Python module's run()).
void AddAllCommands(CLI::App& app);
/// The calibrate command alone, with the options AddAllCommands gives it (the executable hullopt-calibrate).
void AddCalibrateCommandAlone(CLI::App& app);
}  // namespace hullopt::app
