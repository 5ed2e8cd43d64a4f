#pragma once
// `hullopt calibrate` in two executables. The Cs fit is the one command that needs Ceres and the libraries it
// brings (SuiteSparse, BLAS, gfortran, glog); loading them costs every other command several milliseconds of
// start-up. So hullopt does not link them: its main hands a command line whose command is `calibrate` to the
// executable hullopt-calibrate beside it (ExecCalibrateExecutable, before anything is parsed), which parses the
// same command line with the same calibrate command (AddCalibrateCommandAlone) and runs the fit. For the user
// nothing differs: the same options, help, messages, exit codes and files. The Python module links the fit.
#include <string>

namespace hullopt::app {

/// The executable that runs the calibrate command: hullopt-calibrate in the folder of the running executable.
std::string CalibrateExecutablePath();

/// Replaces this process by hullopt-calibrate with the same arguments (argv[0] included, so that usage and
/// error messages read as they would from hullopt). Returns only if that fails: prints the error on stderr and
/// returns the exit code.
int ExecCalibrateExecutable(char** argv);

/// The fit of `hullopt calibrate CONFIG --out DIR` (app/cmd_calibrate.cpp: hullopt-calibrate and the Python
/// module). In hullopt, which hands calibrate command lines on before they are parsed, it only throws.
void RunCalibrate(const std::string& config_file, const std::string& out_dir);

}  // namespace hullopt::app
