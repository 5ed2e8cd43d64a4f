#include "io/config/design_defaults.h"

#include <sstream>
#include <stdexcept>

#include "evaluation/design_frequencies.h"
#include "evaluation/trial_design.h"
#include "io/config/design_config.h"
#include "parametric_hull/design_variables.h"

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

void SkipCampaignBlocks(YamlMap& root, std::vector<std::string>* notes, const std::string& own_command) {
  for (const char* k : {"optimize", "explore", "calibrate", "section", "resistance", "evaluate"}) {
    if (!root.Has(k)) continue;
    root.Skip(k);
    if (notes && k != own_command) notes->push_back(std::string("key '") + k + "' belongs to another command: skipped");
  }
}

void FillDesignDefaults(YamlMap& root, std::vector<std::string>* notes) {
  FillDefaultSeas(root, notes);
  FillDefaultFrequencies(root, notes);
}

void FillDefaultSeas(YamlMap& root, std::vector<std::string>* notes) {
  YAML::Node raw = root.raw();
  if (!root.Has("seas")) {
    raw["seas"] = DefaultSeas();
    if (notes)
      notes->push_back(
          "seas: the sea-state line Hs 0.5..3.0 m, Tz = 4.5 s + 1.0 s/m Hs, JONSWAP gamma 3.3 (default, the "
          "reference paper's): accelerations, MSI and the verdict hold for these head seas only; give the route's "
          "seas (seas:) for its verdict");
  }
}

void FillDefaultFrequencies(YamlMap& root, std::vector<std::string>* notes) {
  YAML::Node raw = root.raw();
  const bool has_solver = root.Has("solver");
  if (has_solver && raw["solver"].IsMap() && raw["solver"]["frequencies"]) return;
  // A throw-away read of the design (the real read follows, with the filled-in tree) for L and U.
  const YAML::Node copy = YAML::Clone(raw);
  YamlMap probe(copy, "", root.file(), YAML::Node(YAML::NodeType::Map));
  // Only the hull at rest and the speed: no mass, no running attitude (the real read builds the design once).
  hull::Hydrostatics hs;
  double speed_m_s = 0.0;
  double g_m_s2 = 0.0;
  try {
    ParsedDesign p = ParseDesign(probe, root.file(), "design");
    ReadHullFile(p);
    hs = hull::ComputeHydrostatics(eval::BuildHull(p.spec, nullptr), p.spec.water.rho_kg_m3);
    speed_m_s = p.spec.speed.MetresPerSecond(hs.L_m, p.spec.water.g_m_s2);
    g_m_s2 = p.spec.water.g_m_s2;
  } catch (const std::exception&) {
    return;  // the clone has no line numbers: the real read names the same fault with its line
  }
  sk::FrequencySpec grid;
  try {
    grid = eval::DesignFrequencyGrid(hs.L_m, speed_m_s, g_m_s2);
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
    s << "solver.frequencies: " << grid.values.size() << " wave frequencies, omega " << grid.values.front()
      << " to " << grid.values.back() << " rad/s (default grid of L " << hs.L_m << " m and U " << speed_m_s
      << " m/s): the RAOs are computed at these frequencies; a peak the grid under-samples is a warning";
    notes->push_back(s.str());
  }
}

void NoteModelDefaults(const YAML::Node& raw, const eval::DesignCase& d, std::vector<std::string>* notes) {
  if (!notes) return;
  auto has = [&](const char* block, const char* key) {
    return raw[block] && raw[block].IsMap() && raw[block][key];
  };
  std::ostringstream s;
  auto push = [&] {
    notes->push_back(s.str());
    s.str("");
  };
  if (!has("solver", "Cs")) {
    s << "solver.Cs = " << d.solver.cs()
      << " (default): sectional viscous damping D = 1/2 Cs rho U v B; with Cs = 0 the heave and pitch peaks are "
         "the potential-flow values, the paper's Cs 0.05-0.15 lowers them (hullopt calibrate fits Cs to tank data)";
    push();
  }
  if (!has("solver", "sections") || !has("solver", "panels")) {
    s << "solver.sections x panels = " << d.solver.rao.sections << " x " << d.solver.rao.panels
      << " (default, the paper's resolution): resolution_check: { enabled: true } reruns the design finer and "
         "reports how far the RAO peaks and MSI move";
    push();
  }
  if (!has("mass", "lcg_m_from_ap")) {
    s << "mass.lcg_m_from_ap = LCB = " << d.mass.lcg_m_from_ap
      << " m (default): the hull floats level; the CG is the pitch axis and fixes the passenger positions";
    push();
  }
  if (!has("mass", "kyy_m") && !has("mass", "kyy_over_L")) {
    s << "mass.kyy_m = " << eval::kDefaultKyyOverL << " L = " << d.mass.kyy_m
      << " m (default, usual for fast craft): the pitch inertia grows with k_yy^2 and sets the pitch natural "
         "frequency; a larger k_yy moves the pitch peak to lower frequency";
    push();
  }
  if (!has("mass", "kg_m") && !has("mass", "kg_over_T")) {
    s << "mass.kg_m = T = " << d.mass.kg_m
      << " m (default): KG does not enter heave and pitch in head seas; it only keeps the hydrostatics plausible";
    push();
  }
  const YAML::Node parametric = raw["hull"] && raw["hull"].IsMap() ? raw["hull"]["parametric"] : YAML::Node();
  if (parametric && parametric.IsMap() && !parametric["freeboard_over_T"]) {
    const double f = hull::DesignVariables{}.freeboard_over_T;
    s << "hull.parametric.freeboard_over_T = " << f << " (default): the deck edge " << f
      << " T above the waterline; the deck-wetness criterion takes it as the freeboard at the bow";
    push();
  }
  if (!raw["msi"]) {
    s << "msi: Lloyd's form of O'Hanlon and McCauley, 2 h exposure (default): the MSI and its criterion refer to "
         "2 h aboard";
    push();
  }
  if (!raw["positions"]) {
    s << "positions: forward, lcg and transom (default, Davis and Holloway 2003): the mean MSI is their mean; "
         "add named points (positions: { points: ... }) for a bridge or a saloon";
    push();
  }
}

}  // namespace hullopt::io
