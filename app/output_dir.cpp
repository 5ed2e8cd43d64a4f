#include "app/output_dir.h"

#include <filesystem>
#include <fstream>

#include "hullopt/version.h"
#include "io/input_error.h"

namespace hullopt::app {

std::string OutPath(const std::string& dir, const std::string& name) {
  return (std::filesystem::path(dir) / name).string();
}

void PrepareOutputDir(const std::string& dir, const std::string& command, const std::string& config_file,
                      const YAML::Node& resolved) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw io::InputError(dir + ": cannot create output folder: " + ec.message());
  std::ofstream cfg(OutPath(dir, "config.resolved.yaml"));
  if (!cfg) throw io::InputError(dir + ": cannot write config.resolved.yaml in the output folder");
  YAML::Emitter em;
  em << resolved;
  cfg << "# hullopt " << kVersion << " — " << command << " " << config_file << "\n"
      << "# The full input of this run with every default filled in; re-run with:\n"
      << "#   hullopt " << command << " config.resolved.yaml --out DIR\n"
      << "# Units: SI unless the key names its unit (_m, _t, _kn, _deg, _s, _pct_L).\n"
      << em.c_str() << "\n";
  std::ofstream ver(OutPath(dir, "VERSION"));
  ver << "hullopt " << kVersion << "\n";
}

}  // namespace hullopt::app
