#pragma once
// The campaign types RunCampaign runs (campaign/campaign_runner.h: CampaignKind).
#include <memory>

#include "campaign/campaign_runner.h"

namespace hullopt::campaign {

/// optimize: evaluation 0 is the base design; then the multistart runs of the NLopt algorithm, one unit of work
/// each (history.csv).
std::unique_ptr<CampaignKind> MakeOptimizeCampaign();

/// explore: a Sobol or Latin-hypercube sample of the design box in sample order (samples.csv), with the
/// sensitivity of the objective to each variable; with several processes in chunks of `chunk` samples per rank
/// and round (0 = 2 x threads).
std::unique_ptr<CampaignKind> MakeExploreCampaign(int chunk);

}  // namespace hullopt::campaign
