// hullopt: hull-form optimisation for high-speed vessels in head seas.
#include <CLI/CLI.hpp>
#include <iostream>

#include "app/commands.h"
#include "hullopt/version.h"
#include "io/input_error.h"

int main(int argc, char** argv) {
  CLI::App app{
      "hullopt — hull-form optimisation of high-speed vessels for seakeeping (time-domain strip theory, "
      "motion sickness incidence)"};
  app.set_version_flag("--version", std::string("hullopt ") + hullopt::kVersion);
  app.require_subcommand(1);
  hullopt::app::AddHullCommand(app);
  hullopt::app::AddSectionCommand(app);
  hullopt::app::AddRaoCommand(app);
  hullopt::app::AddEvaluateCommand(app);
  hullopt::app::AddOptimizeCommand(app);
  hullopt::app::AddExploreCommand(app);
  hullopt::app::AddCalibrateCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const hullopt::io::InputError& e) {
    std::cerr << "hullopt: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "hullopt: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
