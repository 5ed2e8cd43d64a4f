#include "app/commands.h"
#include "io/input_error.h"

namespace hullopt::app {

// Placeholder until the calibrate issue lands: registered so --help lists the whole tool.
void AddCalibrateCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("calibrate", "(not yet available in this version)");
  cmd->allow_extras();
  cmd->callback([] { throw io::InputError("'hullopt calibrate' is not implemented yet in this version"); });
}

}  // namespace hullopt::app
