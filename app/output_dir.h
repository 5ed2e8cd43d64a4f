#pragma once
// Creating a run's output folder and writing what every run leaves behind: the resolved config and the version.
#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>

#include "io/formats/output_lock.h"

namespace hullopt::app {

/// CheckOutputDirConfig, then creates dir (and parents). Writes config.resolved.yaml (with a header naming the tool version, the command
/// and the source config) and VERSION. Throws io::InputError if the folder cannot be created or written.
void PrepareOutputDir(const std::string& dir, const std::string& command, const std::string& config_file,
                      const YAML::Node& resolved);

/// Throws io::InputError if dir holds the output of a different hullopt command (read from the header of its
/// config.resolved.yaml), naming that command; a folder of the same command (a re-run or a resume) passes.
/// Called by PrepareOutputDir, and by the campaigns before they open their journal.
void CheckOutputDirCommand(const std::string& dir, const std::string& command);

/// CheckOutputDirCommand, then, for every command but the campaigns (whose journal holds their resume rules),
/// throws io::InputError if dir's config.resolved.yaml differs from `resolved`, naming the first difference
/// (io::FirstYamlDifference); a re-run with the same config passes. Called by PrepareOutputDir, and before the
/// work starts by the commands that compute (app/run_checks.h), so that a refusal costs nothing.
void CheckOutputDirConfig(const std::string& dir, const std::string& command, const YAML::Node& resolved);

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

/// Path join: dir + "/" + name.
std::string OutPath(const std::string& dir, const std::string& name);

}  // namespace hullopt::app
