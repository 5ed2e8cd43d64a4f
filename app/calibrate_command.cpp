#include "app/calibrate_command.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <string>

#include "app/commands.h"

namespace hullopt::app {

std::string CalibrateExecutablePath() {
  std::string self(4096, '\0');
  const ssize_t n = ::readlink("/proc/self/exe", self.data(), self.size());
  if (n <= 0 || static_cast<std::size_t>(n) >= self.size()) return "hullopt-calibrate";  // then PATH decides
  self.resize(static_cast<std::size_t>(n));
  const std::size_t slash = self.rfind('/');
  return (slash == std::string::npos ? std::string() : self.substr(0, slash + 1)) + "hullopt-calibrate";
}

int ExecCalibrateExecutable(char** argv) {
  const std::string path = CalibrateExecutablePath();
  ::execvp(path.c_str(), argv);
  std::cerr << "hullopt: internal error: cannot run " << path << " (" << std::strerror(errno)
            << "): the calibrate command runs in that executable, installed beside hullopt\n";
  return 3;
}

void AddCalibrateCommand(CLI::App& app) {
  AddConfigCommand(app,
                   {"calibrate",
                    "Fit the sectional damping coefficient Cs to measured heave and pitch RAOs (tank RAO CSV files)",
                    "YAML config with a 'calibrate:' section", "CONFIG"},
                   RunCalibrate);
}

}  // namespace hullopt::app
