#pragma once
// The console and figure options of the commands: --quiet on every command (no result lines on stdout, for
// scripted runs and campaigns; warnings and errors still go to stderr) and --no-plots on the commands that
// draw figures (the numbers only: no SVG figures and no report.html, which shows them). Campaign commands
// carry both in CampaignCliOptions (app/campaign_command.h); the others read them here.
#include <ostream>

#include "app/cli_app.h"

namespace hullopt::app {

/// Adds `--quiet` to a subcommand (AddAllCommands: every command that has no --quiet of its own).
void AddQuietOption(CLI::App* command);
/// Adds `--no-plots` to a subcommand (AddAllCommands: rao, design, evaluate).
void AddNoPlotsOption(CLI::App* command);
/// Whether --quiet / --no-plots was given on this command line.
bool QuietGiven();
bool NoPlotsGiven();
/// Clears both (a new command line is about to be parsed, e.g. by the Python module's run()).
void ResetOutputOptions();
/// std::printf to stdout, unless --quiet.
void Say(const char* format, ...) __attribute__((format(printf, 1, 2)));
/// std::cout, or with --quiet a stream that writes nowhere.
std::ostream& Out();

}  // namespace hullopt::app
