#include "app/commands.h"
#include "io/input_error.h"

namespace hullopt::app {

// Placeholder until the rao issue lands: registered so --help lists the whole tool.
void AddRaoCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("rao", "(not yet available in this version)");
  cmd->allow_extras();
  cmd->callback([] { throw io::InputError("'hullopt rao' is not implemented yet in this version"); });
}

}  // namespace hullopt::app
