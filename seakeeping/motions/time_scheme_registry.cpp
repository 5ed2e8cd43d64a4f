#include "seakeeping/motions/time_scheme_registry.h"

#include <utility>

namespace hullopt::sk {
namespace {

const std::vector<std::pair<TimeSchemeKind, std::string>>& Table() {
  static const std::vector<std::pair<TimeSchemeKind, std::string>> table = {
      {TimeSchemeKind::kWeightedAverageTrapezoid, "weighted_average_trapezoid"},
      {TimeSchemeKind::kPaperSinglePass, "paper_single_pass"},
  };
  return table;
}

}  // namespace

std::vector<std::string> TimeSchemeNames() {
  std::vector<std::string> names;
  for (const auto& [kind, name] : Table()) names.push_back(name);
  return names;
}

std::string TimeSchemeName(TimeSchemeKind kind) {
  for (const auto& [k, name] : Table())
    if (k == kind) return name;
  return "unknown";
}

bool FindTimeScheme(const std::string& name, TimeSchemeKind* kind) {
  for (const auto& [k, n] : Table()) {
    if (n != name) continue;
    *kind = k;
    return true;
  }
  return false;
}

std::unique_ptr<TimeScheme> MakeTimeScheme(TimeSchemeKind kind, const WeightedAverageParameters& parameters) {
  WeightedAverageParameters p = parameters;
  if (kind == TimeSchemeKind::kPaperSinglePass) p.max_passes = 1;
  return std::make_unique<WeightedAverageNewmark>(p);
}

}  // namespace hullopt::sk
