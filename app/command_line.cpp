#include "app/command_line.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <string>
#include <thread>

#include "app/commands.h"
#include "app/mpi_context.h"
#include "hullopt/version.h"
#include "io/formats/input_error.h"

namespace hullopt::app {

int RunCommandLine(int argc, char** argv, const CommandLineVariant& variant) {
  MpiInit(&argc, &argv);
  CLI::App app{
      "hullopt — hull-form optimisation of high-speed vessels for seakeeping (time-domain strip theory, "
      "motion sickness incidence)"};
  app.set_version_flag("--version", std::string("hullopt ") + kVersion + (variant.mpi ? " (mpi)" : ""));
  app.require_subcommand(1);
  if (variant.calibrate_alone) {
    AddCalibrateCommandAlone(app);
  } else {
    AddAllCommands(app);
  }
  int code = 0;
  std::string message;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    code = app.exit(e);
  } catch (const io::InputError& e) {
    message = std::string("hullopt: error: ") + e.what() + "\n";
    code = 1;
  } catch (const std::exception& e) {
    message = std::string("hullopt: internal error: ") + e.what() + "\n";
    code = 3;
  }
  if (!message.empty()) {
    // Under MPI an input error usually occurs on every rank: rank 0 reports it and stops the others (below).
    // Another rank reports only an error of its own, i.e. if rank 0 has not stopped it within the delay.
    if (MpiRank() != 0) std::this_thread::sleep_for(std::chrono::milliseconds(500));
    std::cerr << message;
  }
  // An error on one MPI rank must not leave the others waiting in a collective operation.
  if (code != 0) MpiAbortIfParallel(code);
  MpiFinalize();
  return code;
}

}  // namespace hullopt::app
