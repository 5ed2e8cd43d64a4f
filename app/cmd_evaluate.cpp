#include "app/commands.h"
#include "io/input_error.h"

namespace hullopt::app {

// Placeholder until the evaluate issue lands: registered so --help lists the whole tool.
void AddEvaluateCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("evaluate", "(not yet available in this version)");
  cmd->allow_extras();
  cmd->callback([] { throw io::InputError("'hullopt evaluate' is not implemented yet in this version"); });
}

}  // namespace hullopt::app
