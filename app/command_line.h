#pragma once
// The command line of the hullopt executables: parse it, run the chosen command, turn errors into one line and
// an exit code (0 done, 1 bad input, 2 bad command line, 3 internal error). Compiled once for all executables,
// which differ only in the flags they pass (main.cpp), so CLI11 is compiled here and not in each main.

namespace hullopt::app {

/// Which executable runs the command line.
struct CommandLineVariant {
  bool calibrate_alone = false;  ///< hullopt-calibrate: the calibrate command only (AddCalibrateCommandAlone)
  bool mpi = false;              ///< built with MPI: `--version` says so
};

/// Initialises MPI (a no-op in a serial build), registers the commands, parses argv and runs the command;
/// returns the process's exit code after MPI is finalised.
int RunCommandLine(int argc, char** argv, const CommandLineVariant& variant);

}  // namespace hullopt::app
