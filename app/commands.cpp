#include "app/commands.h"

namespace hullopt::app {

void AddAllCommands(CLI::App& app) {
  AddHullCommand(app);
  AddSectionCommand(app);
  AddRaoCommand(app);
  AddCoefficientsCommand(app);
  AddEvaluateCommand(app);
  AddOptimizeCommand(app);
  AddExploreCommand(app);
  AddCalibrateCommand(app);
  AddResistanceCommand(app);
}

}  // namespace hullopt::app
