#pragma once
// Files named in a config (offsets, STL, tank data, RAO tables, design configs, scatter diagrams): one rule for
// every command. A relative path is relative to the folder of the config file that names it (a nested config's
// paths to its own folder); an absolute path is used as it is. The working folder plays no part.
#include <string>
#include <vector>

#include "io/config/yaml_map.h"

namespace hullopt::io {

/// The path `given` (as written in config_file) resolved by the rule above, absolute and lexically normal.
/// config_file is the config's path as the program was given it (relative to the working folder or absolute).
std::string ResolveConfigPath(const std::string& given, const std::string& config_file);

/// The file named by m's text key `key`, resolved against m.file(). The resolved tree records the absolute path,
/// so config.resolved.yaml re-runs from any folder. Throws InputError naming the key, the path as written and
/// the path it resolved to when no such file exists.
std::string ConfigFilePath(YamlMap& m, const std::string& key);

/// As ConfigFilePath for a key that lists files.
std::vector<std::string> ConfigFilePaths(YamlMap& m, const std::string& key);

}  // namespace hullopt::io
