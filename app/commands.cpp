#include "app/commands.h"

#include "app/run_checks.h"

namespace hullopt::app {

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
}

}  // namespace hullopt::app
