#pragma once
// A single design's config with the defaults a designer need not type filled in before it is read, so that
// config.resolved.yaml holds them and re-runs to the same result (`hullopt design`, `hullopt evaluate` on a
// hull config):
//   seas:               the reference paper's sea-state line, Hs 0.5 to 3.0 m by 0.5 m, JONSWAP gamma 3.3
//                       (Tz = 4.5 s + 1.0 s/m Hs), as in configs/davis-holloway-2003.yaml
//   solver.frequencies: eval::DesignFrequencyGrid of the hull's L and the speed (a range in omega_rad_s)
// mass (LCG = LCB, k_yy = 0.25 L, KG = T), msi (lloyd, 2 h) and the positions forward / LCG / transom are the
// readers' own defaults (io/config/motion_config.h, io/config/seas_config.h).
#include <string>
#include <vector>

#include "evaluation/design_case.h"
#include "io/config/yaml_map.h"

namespace hullopt::io {

/// The default `seas:` entry (one sea_state_line).
YAML::Node DefaultSeas();

/// Marks the blocks of other commands (optimize, explore, calibrate, section, resistance, evaluate) as read,
/// one note each but for own_command's block (the command that runs the config, e.g. a campaign's report of
/// its own baseline): a campaign config or best.yaml runs as the design it describes.
void SkipCampaignBlocks(YamlMap& root, std::vector<std::string>* notes, const std::string& own_command = "");

/// Fills root's raw tree in place: `seas` when absent, `solver.frequencies` when absent (the hull at rest is
/// built once to find L and U, without mass or running attitude; its errors are left to the real read).
/// Appends one line per default taken to *notes. FillDesignDefaults is FillDefaultSeas then
/// FillDefaultFrequencies; a caller that checks the whole config first puts its check between them.
void FillDesignDefaults(YamlMap& root, std::vector<std::string>* notes);
void FillDefaultSeas(YamlMap& root, std::vector<std::string>* notes);
void FillDefaultFrequencies(YamlMap& root, std::vector<std::string>* notes);

/// One line per model default the design took (solver Cs, sections and panels; mass LCG, k_yy, KG; msi), each
/// with its value and its effect on the results: raw is the config as written (after FillDesignDefaults),
/// design the case read from it. The lines for seas and frequencies come from FillDesignDefaults.
void NoteModelDefaults(const YAML::Node& raw, const eval::DesignCase& design, std::vector<std::string>* notes);

}  // namespace hullopt::io
