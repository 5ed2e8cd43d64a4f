#include "io/config/campaign_outputs.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "io/formats/finite_json.h"
#include "io/formats/atomic_file.h"
#include "io/formats/input_error.h"

namespace hullopt::io {

std::string TextHash(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

void WriteJson(const std::string& path, const nlohmann::json& json) {
  RequireFiniteJson(json, path);
  WriteFileAtomically(path, json.dump(2) + "\n");
}

void WriteBestYaml(const std::string& path, const YAML::Node& base_config, const std::string& block,
                   const std::vector<std::string>& names, const std::vector<std::string>& start_source,
                   const std::vector<double>& best_x, const std::string& comment) {
  YAML::Node cfg = YAML::Clone(base_config);
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (start_source[i] == "hull.parametric") {
      cfg["hull"]["parametric"][names[i]] = best_x[i];
    } else {
      cfg[block]["start"][names[i]] = best_x[i];
    }
  }
  YAML::Emitter em;
  em.SetDoublePrecision(17);
  em << cfg;
  WriteFileAtomically(path, "# " + comment + "\n" + em.c_str() + "\n");
}

void WriteSensitivityCsv(const std::string& path, const std::vector<std::string>& names,
                         const opt::SensitivityResult& s) {
  std::string text = "variable,src,first_order_sobol\n";
  char buf[96];
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::snprintf(buf, sizeof buf, ",%.9g,%.9g\n", s.src[i], s.first_order[i]);
    text += names[i] + buf;
  }
  WriteFileAtomically(path, text);
}

std::string ReadTextFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) return "";
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace hullopt::io
