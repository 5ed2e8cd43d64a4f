#pragma once
// A run's output folder: creating it and writing what every run leaves behind (the resolved config and the
// version), and the checks that keep one folder to one command and one config.
#include <yaml-cpp/yaml.h>

#include <string>

namespace hullopt::io {

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

/// Path join: dir + "/" + name.
std::string OutPath(const std::string& dir, const std::string& name);

}  // namespace hullopt::io
