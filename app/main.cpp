// hullopt: hull-form optimisation for high-speed vessels in head seas.
#include <CLI/CLI.hpp>
#include <iostream>

#include "app/commands.h"
#include "app/mpi_context.h"
#include "hullopt/version.h"
#include "io/input_error.h"

int main(int argc, char** argv) {
  hullopt::app::MpiInit(&argc, &argv);
  CLI::App app{
      "hullopt — hull-form optimisation of high-speed vessels for seakeeping (time-domain strip theory, "
      "motion sickness incidence)"};
#ifdef HULLOPT_HAVE_MPI
  app.set_version_flag("--version", std::string("hullopt ") + hullopt::kVersion + " (mpi)");
#else
  app.set_version_flag("--version", std::string("hullopt ") + hullopt::kVersion);
#endif
  app.require_subcommand(1);
  hullopt::app::AddHullCommand(app);
  hullopt::app::AddSectionCommand(app);
  hullopt::app::AddRaoCommand(app);
  hullopt::app::AddEvaluateCommand(app);
  hullopt::app::AddOptimizeCommand(app);
  hullopt::app::AddExploreCommand(app);
  hullopt::app::AddCalibrateCommand(app);
  int code = 0;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    code = app.exit(e);
  } catch (const hullopt::io::InputError& e) {
    std::cerr << "hullopt: error: " << e.what() << "\n";
    code = 1;
  } catch (const std::exception& e) {
    std::cerr << "hullopt: internal error: " << e.what() << "\n";
    code = 3;
  }
  // An error on one MPI rank must not leave the others waiting in a collective operation.
  if (code != 0) hullopt::app::MpiAbortIfParallel(code);
  hullopt::app::MpiFinalize();
  return code;
}
