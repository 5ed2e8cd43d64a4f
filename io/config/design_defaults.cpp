#include "io/config/design_defaults.h"

#include <sstream>
#include <stdexcept>

#include "evaluation/design_frequencies.h"
#include "io/config/design_config.h"

namespace hullopt::io {

YAML::Node DefaultSeas() {
  YAML::Node line;
  for (double hs : {0.5, 1.0, 1.5, 2.0, 2.5, 3.0}) line["Hs_m"].push_back(hs);
  line["gamma"] = 3.3;
  YAML::Node entry;
  entry["sea_state_line"] = line;
  YAML::Node seas(YAML::NodeType::Sequence);
  seas.push_back(entry);
  return seas;
}

void SkipCampaignBlocks(YamlMap& root, std::vector<std::string>* notes) {
  for (const char* k : {"optimize", "explore", "calibrate", "section", "resistance", "evaluate"}) {
    if (!root.Has(k)) continue;
    root.Skip(k);
    if (notes) notes->push_back(std::string("key '") + k + "' belongs to another command: skipped");
  }
}

void FillDesignDefaults(YamlMap& root, std::vector<std::string>* notes) {
  YAML::Node raw = root.raw();
  if (!root.Has("seas")) {
    raw["seas"] = DefaultSeas();
    if (notes) notes->push_back("seas: the sea-state line Hs 0.5..3.0 m, Tz = 4.5 s + 1.0 s/m Hs, JONSWAP gamma 3.3 (default)");
  }
  const bool has_solver = root.Has("solver");
  if (has_solver && raw["solver"].IsMap() && raw["solver"]["frequencies"]) return;
  // A throw-away read of the design (the real read follows, with the filled-in tree) for L and U.
  const YAML::Node copy = YAML::Clone(raw);
  YamlMap probe(copy, "", root.file(), YAML::Node(YAML::NodeType::Map));
  eval::DesignCase d;
  try {
    d = LoadDesignCase(probe, root.file(), "design");
  } catch (const InputError&) {
    return;  // the clone has no line numbers: the real read names the same fault with its line
  }
  sk::FrequencySpec grid;
  try {
    grid = eval::DesignFrequencyGrid(d.hydrostatics.L_m, d.speed_m_s, d.water.g_m_s2);
  } catch (const std::invalid_argument& e) {
    throw InputError(root.file() + ": " + e.what());
  }
  YAML::Node range;
  range["quantity"] = "omega_rad_s";
  range["from"] = grid.values.front();
  range["to"] = grid.values.back();
  range["count"] = static_cast<int>(grid.values.size());
  if (!has_solver) raw["solver"] = YAML::Node(YAML::NodeType::Map);
  raw["solver"]["frequencies"]["range"] = range;
  if (notes) {
    std::ostringstream s;
    s << "solver.frequencies: " << grid.values.size() << " wave frequencies, omega " << grid.values.front() << " to "
      << grid.values.back() << " rad/s (default grid of L " << d.hydrostatics.L_m << " m and U " << d.speed_m_s
      << " m/s)";
    notes->push_back(s.str());
  }
}

}  // namespace hullopt::io
