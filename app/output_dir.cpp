#include "app/output_dir.h"

#include <cstdio>
#include <filesystem>
#include <utility>

#include "app/mpi_context.h"
#include "io/formats/input_error.h"
#include "io/formats/utf8_text.h"

namespace hullopt::app {

OutputFolderGuard::OutputFolderGuard(const std::string& dir, const std::string& command,
                                     const std::string& config_file) {
  for (const auto& [what, path] : {std::pair<const char*, const std::string&>{"--out", dir},
                                   std::pair<const char*, const std::string&>{"config", config_file}}) {
    if (!io::IsValidUtf8(path))
      throw io::InputError(std::string("command line: the ") + what +
                           " path is not valid UTF-8 (paths are written to JSON outputs); rename it");
  }
  std::string error, stale;
  if (MpiRank() == 0) {
    try {
      lock_ = std::make_unique<io::OutputFolderLock>(dir, command, &stale);
    } catch (const io::InputError& e) {
      error = e.what();
    }
  }
  error = MpiBroadcast(error);
  if (!error.empty()) throw io::InputError(error);
  if (!stale.empty())
    std::fprintf(stderr, "hullopt: note: %s: took over the lock left by %s, which is no longer running\n",
                 dir.c_str(), stale.c_str());
}

OutputFolderGuard::~OutputFolderGuard() = default;

}  // namespace hullopt::app
