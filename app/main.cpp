// hullopt: hull-form optimisation for high-speed vessels in head seas.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstring>
#include <iostream>
#include <thread>

#include "app/calibrate_command.h"
#include "app/commands.h"
#include "app/mpi_context.h"
#include "hullopt/version.h"
#include "io/formats/input_error.h"

int main(int argc, char** argv) {
#ifndef HULLOPT_CALIBRATE_EXECUTABLE
  // `hullopt calibrate ...` runs in hullopt-calibrate, the executable that links the Cs fit's libraries (Ceres),
  // so that no other command loads them (app/calibrate_command.h).
  if (argc > 1 && std::strcmp(argv[1], "calibrate") == 0) return hullopt::app::ExecCalibrateExecutable(argv);
#endif
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
#ifdef HULLOPT_CALIBRATE_EXECUTABLE
  hullopt::app::AddCalibrateCommandAlone(app);
#else
  hullopt::app::AddAllCommands(app);
#endif
  int code = 0;
  std::string message;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    code = app.exit(e);
  } catch (const hullopt::io::InputError& e) {
    message = std::string("hullopt: error: ") + e.what() + "\n";
    code = 1;
  } catch (const std::exception& e) {
    message = std::string("hullopt: internal error: ") + e.what() + "\n";
    code = 3;
  }
  if (!message.empty()) {
    // Under MPI an input error usually occurs on every rank: rank 0 reports it and stops the others (below).
    // Another rank reports only an error of its own, i.e. if rank 0 has not stopped it within the delay.
    if (hullopt::app::MpiRank() != 0) std::this_thread::sleep_for(std::chrono::milliseconds(500));
    std::cerr << message;
  }
  // An error on one MPI rank must not leave the others waiting in a collective operation.
  if (code != 0) hullopt::app::MpiAbortIfParallel(code);
  hullopt::app::MpiFinalize();
  return code;
}
