#include "app/commands.h"
#include "io/input_error.h"

namespace hullopt::app {

// Placeholder until the section issue lands: registered so --help lists the whole tool.
void AddSectionCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("section", "(not yet available in this version)");
  cmd->allow_extras();
  cmd->callback([] { throw io::InputError("'hullopt section' is not implemented yet in this version"); });
}

}  // namespace hullopt::app
