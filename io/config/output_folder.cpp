#include "io/config/output_folder.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "hullopt/version.h"
#include "io/config/yaml_difference.h"
#include "io/formats/atomic_file.h"
#include "io/formats/input_error.h"

namespace hullopt::io {

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
    throw InputError(dir + ": this folder holds the output of 'hullopt " + earlier +
                         "' (see its config.resolved.yaml); 'hullopt " + command +
                         "' will not write over it: use another --out folder");
}

void CheckOutputDirConfig(const std::string& dir, const std::string& command, const YAML::Node& resolved) {
  CheckOutputDirCommand(dir, command);
  // The campaigns' journal decides about their folders (resume with the same config, start over once the log
  // is deleted); every other command writes one result, which must not be mixed with another config's files.
  if (command == "optimize" || command == "explore") return;
  const std::string path = OutPath(dir, "config.resolved.yaml");
  std::ifstream in(path);
  if (!in) return;
  std::stringstream text;
  text << in.rdbuf();
  std::string change;
  try {
    change = FirstYamlDifference(YAML::Load(text.str()), resolved);
  } catch (const YAML::Exception& e) {
    change = "its config.resolved.yaml does not read as YAML (" + std::string(e.what()) + ")";
  }
  if (change.empty()) return;
  throw InputError(dir + ": this folder holds the output of 'hullopt " + command +
                       "' run with a different config (first difference: " + change +
                       "); a folder holds one config's results: use another --out folder, or delete " + path +
                       " to let this run replace them");
}

void PrepareOutputDir(const std::string& dir, const std::string& command, const std::string& config_file,
                      const YAML::Node& resolved) {
  CheckOutputDirConfig(dir, command, resolved);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir + ": cannot create output folder: " + ec.message());
  YAML::Emitter em;
  std::ostringstream cfg;
  em << resolved;
  cfg << "# hullopt " << kVersion << " — " << command << " " << config_file << "\n"
      << "# The full input of this run with every default filled in; re-run with:\n"
      << "#   hullopt " << command << " config.resolved.yaml --out DIR\n"
      << "# Units: SI unless the key names its unit (_m, _t, _kn, _deg, _s, _pct_L).\n"
      << em.c_str() << "\n";
  WriteFileAtomically(OutPath(dir, "config.resolved.yaml"), cfg.str());
  WriteFileAtomically(OutPath(dir, "VERSION"), std::string("hullopt ") + kVersion + "\n");
}

}  // namespace hullopt::io
