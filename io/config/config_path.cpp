#include "io/config/config_path.h"

#include <filesystem>

namespace hullopt::io {
namespace {

namespace fs = std::filesystem;

// Why a resolved path is not there: the resolved path, and for a relative one the folder it was taken from.
std::string MissingFile(const std::string& given, const std::string& file, const std::string& config_file) {
  if (fs::path(given).is_absolute()) return "no such file";
  const fs::path folder = fs::path(ResolveConfigPath(".", config_file)).parent_path();
  return "no such file " + file + " (a relative path is relative to the config's folder, " + folder.string() + ")";
}

bool Exists(const std::string& file) {
  std::error_code ec;
  return fs::exists(file, ec);
}

}  // namespace

std::string ResolveConfigPath(const std::string& given, const std::string& config_file) {
  const fs::path p(given);
  if (p.is_absolute()) return p.lexically_normal().string();
  return fs::absolute(fs::path(config_file).parent_path() / p).lexically_normal().string();
}

std::string ConfigFilePath(YamlMap& m, const std::string& key) {
  const std::string given = m.String(key);
  if (given.empty()) m.Fail(key, "must name a file");
  const std::string file = ResolveConfigPath(given, m.file());
  if (!Exists(file)) m.Fail(key, MissingFile(given, file, m.file()));
  m.resolved()[key] = file;
  return file;
}

std::vector<std::string> ConfigFilePaths(YamlMap& m, const std::string& key) {
  std::vector<std::string> files = m.Strings(key);
  YAML::Node seq(YAML::NodeType::Sequence);
  for (auto& f : files) {
    const std::string given = f;
    if (given.empty()) m.Fail(key, "an element is empty: each must name a file");
    f = ResolveConfigPath(given, m.file());
    if (!Exists(f)) m.Fail(key, "'" + given + "': " + MissingFile(given, f, m.file()));
    seq.push_back(f);
  }
  m.resolved()[key] = seq;
  return files;
}

}  // namespace hullopt::io
