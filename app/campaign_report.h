#pragma once
// report.html of a campaign folder (optimize, explore): the baseline (the campaign config's own design) beside
// the best design (best.yaml) — hydrostatics, body plans, RAOs, MSI per sea and position — and the campaign's
// convergence and variable plots. Both designs are evaluated once here, with the design defaults of
// io/config/design_defaults.h for what the campaign config does not give.
#include <string>
#include <vector>

namespace hullopt::app {

/// Writes out/report.html (and out/baseline_bodyplan.svg, out/best_bodyplan.svg, out/baseline_vs_best_rao.svg).
/// out must hold best.yaml. Nothing for a campaign config without `hull:` (an analytic objective). command names the campaign (optimize, explore) in the title and cost line.
/// campaign_warnings: what the campaign found about its best design (its evaluation's warning, the resolution
/// check, how many evaluations carried a warning), listed with the warnings of the re-evaluation. active_set:
/// one line per design variable at a bound and per constraint active at the best design.
void WriteCampaignReport(const std::string& out, const std::string& command, const std::string& config_file,
                         const std::vector<std::string>& campaign_warnings = {},
                         const std::vector<std::string>& active_set = {});

}  // namespace hullopt::app
