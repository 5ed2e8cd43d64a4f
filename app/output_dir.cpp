#include "app/output_dir.h"

#include <filesystem>
#include <fstream>

#include "hullopt/version.h"
#include "io/input_error.h"

namespace hullopt::app {

std::string OutPath(const std::string& dir, const std::string& name) {
  return (std::filesystem::path(dir) / name).string();
}

void CheckOutputDirCommand(const std::string& dir, const std::string& command) {
  std::ifstream in(OutPath(dir, "config.resolved.yaml"));
  std::string first;
  if (!in || !std::getline(in, first)) return;
  // Header written below: "# hullopt <version> — <command> <config>".
  const std::string sep = " — ";
  const auto at = first.find(sep);
  if (first.rfind("# hullopt ", 0) != 0 || at == std::string::npos) return;
  const std::string rest = first.substr(at + sep.size());
  const std::string earlier = rest.substr(0, rest.find(' '));
  if (earlier != command)
    throw io::InputError(dir + ": this folder holds the output of 'hullopt " + earlier +
                         "' (see its config.resolved.yaml); 'hullopt " + command +
                         "' will not write over it: use another --out folder");
}

void PrepareOutputDir(const std::string& dir, const std::string& command, const std::string& config_file,
                      const YAML::Node& resolved) {
  CheckOutputDirCommand(dir, command);
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
