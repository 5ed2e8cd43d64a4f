#include "app/commands.h"

#include <CLI/CLI.hpp>
#include <cstring>
#include <memory>

#include "app/output_dir.h"
#include "app/output_options.h"
#include "app/run_checks.h"

namespace hullopt::app {

CLI::App* AddConfigCommand(CLI::App& app, const CommandText& text,
                           std::function<void(const std::string& config, const std::string& out)> run) {
  auto* cmd = app.add_subcommand(text.name, text.description);
  auto config = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>(text.default_out ? text.default_out : "");
  cmd->add_option(text.config_name, *config, text.config_help)->required();
  auto* out_option = cmd->add_option("--out", *out, text.out_help);
  if (text.default_out) {
    out_option->capture_default_str();
  } else {
    out_option->required();
  }
  const std::string name = text.name;
  cmd->callback([config, out, name, run = std::move(run)] {
    const OutputFolderGuard lock(*out, name, *config);
    run(*config, *out);
  });
  return cmd;
}

namespace {

// --force on the commands that run the strip solver (they estimate its cost first, app/run_checks.h), --quiet
// on every command (campaigns have their own), --no-plots on the single-run commands that draw figures
// (campaigns: AddCampaignCommand); each on those of the named commands the app has.
void AddCommonOptions(CLI::App& app) {
  const auto named = [&app](const char* name) -> CLI::App* {
    for (CLI::App* command : app.get_subcommands({}))
      if (command->get_name() == name) return command;
    return nullptr;
  };
  ResetForceOption();
  for (const char* name : {"section", "rao", "coefficients", "design", "evaluate", "optimize", "explore", "calibrate"})
    if (CLI::App* command = named(name)) AddForceOption(command);
  ResetOutputOptions();
  for (CLI::App* command : app.get_subcommands({}))
    if (command->get_option_no_throw("--quiet") == nullptr) AddQuietOption(command);
  for (const char* name : {"rao", "design", "evaluate"})
    if (CLI::App* command = named(name)) AddNoPlotsOption(command);
}

}  // namespace

void AddAllCommands(CLI::App& app) {
  AddHullCommand(app);
  AddSectionCommand(app);
  AddRaoCommand(app);
  AddCoefficientsCommand(app);
  AddDesignCommand(app);
  AddEvaluateCommand(app);
  AddOptimizeCommand(app);
  AddExploreCommand(app);
  AddCalibrateCommand(app);
  AddResistanceCommand(app);
  AddCommonOptions(app);
}

void AddCalibrateCommandAlone(CLI::App& app) {
  AddCalibrateCommand(app);
  AddCommonOptions(app);
}

}  // namespace hullopt::app
