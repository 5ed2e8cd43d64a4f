#include "optimizer/design_sampling.h"

#include <numeric>
#include <stdexcept>

#include "optimizer/seeded_random.h"
#include "optimizer/sobol_sequence.h"

namespace hullopt::opt {

std::vector<std::vector<double>> LatinHypercube(int n, int d, std::uint64_t seed) {
  if (n < 1 || d < 1) throw std::invalid_argument("Latin hypercube: need n >= 1 and d >= 1");
  SeededRandom rng(seed);
  std::vector<std::vector<double>> pts(n, std::vector<double>(d));
  std::vector<int> perm(n);
  for (int j = 0; j < d; ++j) {
    std::iota(perm.begin(), perm.end(), 0);
    for (int i = n - 1; i > 0; --i) std::swap(perm[i], perm[rng.Below(static_cast<std::uint64_t>(i) + 1)]);
    for (int i = 0; i < n; ++i) pts[i][j] = (perm[i] + rng.Uniform()) / n;
  }
  return pts;
}

std::vector<std::vector<double>> SobolPoints(int n, int d) {
  if (n < 1) throw std::invalid_argument("Sobol points: need n >= 1");
  SobolSequence seq(d);
  std::vector<std::vector<double>> pts;
  pts.reserve(n);
  for (int i = 1; i <= n; ++i) pts.push_back(seq.Point(static_cast<std::uint64_t>(i)));
  return pts;
}

std::vector<std::vector<double>> SampleDesigns(const CampaignDefinition& campaign, const std::string& method,
                                               int n) {
  const int d = static_cast<int>(campaign.variables.size());
  std::vector<std::vector<double>> unit;
  if (method == "sobol") {
    unit = SobolPoints(n, d);
  } else if (method == "lhs") {
    unit = LatinHypercube(n, d, campaign.seed);
  } else {
    throw std::invalid_argument("sampling method '" + method + "': must be sobol or lhs");
  }
  for (auto& p : unit) {
    for (int j = 0; j < d; ++j) {
      const auto& v = campaign.variables[j];
      p[j] = v.lower + (v.upper - v.lower) * p[j];
    }
  }
  return unit;
}

}  // namespace hullopt::opt
