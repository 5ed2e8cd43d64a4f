#pragma once
// The lock a command holds on its output folder for its whole run; the folder functions (io/config/output_folder.h).
#include <memory>
#include <string>

#include "io/config/output_folder.h"
#include "io/formats/output_lock.h"

namespace hullopt::app {

// The folder functions live in io/config/output_folder.h; the commands name them here.
using io::CheckOutputDirCommand;
using io::CheckOutputDirConfig;
using io::OutPath;
using io::PrepareOutputDir;

/// The output folder's lock for the whole run of a command (io::OutputFolderLock): taken by MPI rank 0 only
/// (the only writer); a refusal is shared so that every rank stops with the same error. Prints a note on stderr
/// when it takes over the stale lock of a run that was killed. The folder and config paths are checked to be
/// UTF-8 first (they appear in JSON outputs and messages).
class OutputFolderGuard {
 public:
  OutputFolderGuard(const std::string& dir, const std::string& command, const std::string& config_file);
  ~OutputFolderGuard();

 private:
  std::unique_ptr<io::OutputFolderLock> lock_;
};

}  // namespace hullopt::app
