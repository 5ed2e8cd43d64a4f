// hullopt: hull-form optimisation for high-speed vessels in head seas. The same main serves hullopt, its MPI
// variant and hullopt-calibrate; the command line itself is app/command_line.cpp.
#include <cstring>

#include "app/calibrate_command.h"
#include "app/command_line.h"

int main(int argc, char** argv) {
  hullopt::app::CommandLineVariant variant;
#ifdef HULLOPT_CALIBRATE_EXECUTABLE
  variant.calibrate_alone = true;
#else
  // `hullopt calibrate ...` runs in hullopt-calibrate, the executable that links the Cs fit's libraries (Ceres),
  // so that no other command loads them (app/calibrate_command.h).
  if (argc > 1 && std::strcmp(argv[1], "calibrate") == 0) return hullopt::app::ExecCalibrateExecutable(argv);
#endif
#ifdef HULLOPT_HAVE_MPI
  variant.mpi = true;
#endif
  return hullopt::app::RunCommandLine(argc, argv, variant);
}
