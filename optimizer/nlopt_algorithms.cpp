#include "optimizer/nlopt_algorithms.h"

#include <nlopt.h>

#include <algorithm>

namespace hullopt::opt {
namespace {
bool StartsWith(const std::string& s, const std::string& p) { return s.compare(0, p.size(), p) == 0; }
}  // namespace

bool IsNloptAlgorithm(const std::string& name) {
  const auto names = NloptAlgorithmNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::vector<std::string> NloptAlgorithmNames() {
  std::vector<std::string> out;
  for (int a = 0; a < NLOPT_NUM_ALGORITHMS; ++a) {
    const char* s = nlopt_algorithm_to_string(static_cast<nlopt_algorithm>(a));
    if (s != nullptr) out.emplace_back(s);
  }
  return out;
}

std::vector<std::string> CampaignAlgorithmNames() {
  std::vector<std::string> out;
  for (const auto& n : NloptAlgorithmNames())
    if (!NeedsGradient(n) && !NeedsSubsidiaryOptimizer(n)) out.push_back(n);
  return out;
}

bool NeedsGradient(const std::string& name) { return StartsWith(name, "LD_") || StartsWith(name, "GD_"); }

bool NeedsSubsidiaryOptimizer(const std::string& name) {
  return StartsWith(name, "AUGLAG") || StartsWith(name, "G_MLSL") || StartsWith(name, "GN_MLSL") ||
         StartsWith(name, "GD_MLSL");
}

bool IsGlobal(const std::string& name) { return StartsWith(name, "G"); }

bool SupportsInequalityConstraints(const std::string& name) {
  // NLopt reference, "Nonlinear constraints": COBYLA, ISRES, ORIG_DIRECT(_L), AGS, MMA, CCSAQ, SLSQP, AUGLAG.
  static const char* const kWith[] = {"LN_COBYLA", "GN_ISRES", "GN_ORIG_DIRECT", "GN_ORIG_DIRECT_L",
                                      "GN_AGS",    "LD_MMA",   "LD_CCSAQ",       "LD_SLSQP"};
  for (const char* w : kWith)
    if (name == w) return true;
  return StartsWith(name, "AUGLAG");
}

bool IsStochastic(const std::string& name) {
  return name == "GN_ISRES" || name == "GN_ESCH" || StartsWith(name, "GN_CRS2") || name == "GN_MLSL" ||
         name == "GN_MLSL_LDS" || name == "GN_AGS" || name == "LN_PRAXIS";
}

}  // namespace hullopt::opt
