#pragma once
// Space-filling samples of a campaign's design box for exploration: Sobol or Latin hypercube.
#include <cstdint>
#include <string>
#include <vector>

#include "optimizer/campaign.h"

namespace hullopt::opt {

/// Latin hypercube of n points in [0, 1)^d: in every dimension each of the n equal strata holds exactly one
/// point, placed uniformly inside its stratum; strata permutations from a stream seeded by `seed`.
std::vector<std::vector<double>> LatinHypercube(int n, int d, std::uint64_t seed);

/// Sobol points 1..n in [0, 1)^d (the origin, point 0, is skipped: it is a corner of the design box).
std::vector<std::vector<double>> SobolPoints(int n, int d);

/// n designs of the campaign's variable box by method "sobol" or "lhs" (unit samples scaled to the bounds).
/// Throws std::invalid_argument for an unknown method or n < 1.
std::vector<std::vector<double>> SampleDesigns(const CampaignDefinition& campaign, const std::string& method,
                                               int n);

}  // namespace hullopt::opt
