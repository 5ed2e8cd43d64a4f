#include "io/config_path.h"

#include <filesystem>

namespace hullopt::io {

std::string ResolveConfigPath(const std::string& given, const std::string& config_file) {
  namespace fs = std::filesystem;
  if (fs::path(given).is_absolute() || fs::exists(given)) return given;
  const fs::path beside = fs::path(config_file).parent_path() / given;
  return fs::exists(beside) ? beside.string() : given;
}

}  // namespace hullopt::io
