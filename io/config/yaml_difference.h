#pragma once
// The first difference between two YAML trees, for messages that say what changed (e.g. why a campaign folder
// is refused for resumption: the resolved config of the earlier run against this one's).
#include <yaml-cpp/yaml.h>

#include <string>

namespace hullopt::io {

/// "" when the trees are equal (scalars compared as emitted text, or as numbers when both read as one); otherwise one phrase naming the dotted key
/// path and both values, e.g. "key 'solver.sectional_force': absent before, now 'momentum'". Keys are visited
/// in the order of `now`, then keys only in `before`.
std::string FirstYamlDifference(const YAML::Node& before, const YAML::Node& now);

}  // namespace hullopt::io
