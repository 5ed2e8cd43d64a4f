// RunCalibrate of the hullopt executable, which does not link the Cs fit: its main hands calibrate command
// lines to hullopt-calibrate before parsing them (app/calibrate_command.h), so this is never reached.
#include <stdexcept>

#include "app/calibrate_command.h"

namespace hullopt::app {

void RunCalibrate(const std::string&, const std::string&) {
  throw std::logic_error("the calibrate command runs in the executable hullopt-calibrate, not in hullopt");
}

}  // namespace hullopt::app
