#include "io/report/design_variable_label.h"

#include "parametric_hull/design_variables.h"

namespace hullopt::io {
namespace {

void ReplaceEvery(std::string* s, const std::string& from, const std::string& to) {
  for (size_t p = s->find(from); p != std::string::npos; p = s->find(from, p + to.size())) s->replace(p, from.size(), to);
}

}  // namespace

std::string DesignVariableName(const std::string& key) {
  if (hull::FindDesignVariable(key) == nullptr) return key;
  std::string name = key;
  // The unit goes into the axis label, not the name.
  for (const char* suffix : {"_pct_L", "_m", "_t"})
    if (name.size() > std::string(suffix).size() && name.compare(name.size() - std::string(suffix).size(),
                                                                 std::string::npos, suffix) == 0)
      name.erase(name.size() - std::string(suffix).size());
  ReplaceEvery(&name, "_over_", "/");
  ReplaceEvery(&name, "_", " ");
  return name;
}

std::string DesignVariableAxisLabel(const std::string& key) {
  const hull::DesignVariableField* field = hull::FindDesignVariable(key);
  if (field == nullptr) return key;
  return DesignVariableName(key) + " [" + field->unit + "]";
}

}  // namespace hullopt::io
