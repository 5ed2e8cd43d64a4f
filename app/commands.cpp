#include "app/commands.h"

#include <CLI/CLI.hpp>
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
  // The commands that run the strip solver estimate its cost first (app/run_checks.h).
  ResetForceOption();
  for (const char* name : {"section", "rao", "coefficients", "design", "evaluate", "optimize", "explore", "calibrate"})
    AddForceOption(app.get_subcommand(name));
  // --quiet on every command (campaigns have their own), --no-plots on the single-run commands that draw
  // figures (campaigns: AddCampaignCommand).
  ResetOutputOptions();
  for (CLI::App* command : app.get_subcommands({}))
    if (command->get_option_no_throw("--quiet") == nullptr) AddQuietOption(command);
  for (const char* name : {"rao", "design", "evaluate"}) AddNoPlotsOption(app.get_subcommand(name));
}

}  // namespace hullopt::app
