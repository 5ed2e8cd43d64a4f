#pragma once
// Data files named in a config (offsets, tank data, RAO tables): one rule for every command.
#include <string>

namespace hullopt::io {

/// The path as given if it is absolute or exists relative to the working folder, else the same path relative
/// to the config file's folder when that exists; otherwise as given (so the reader's "cannot open" error
/// names what the user wrote).
std::string ResolveConfigPath(const std::string& given, const std::string& config_file);

}  // namespace hullopt::io
