#pragma once
// Readable plot labels of the design variables: "LCF_pct_L" → "LCF" and "LCF [% L]", "L_over_B" → "L/B [-]",
// with the unit from the design-variable table (parametric_hull/design_variables.h). A name that is not a
// design variable (an analytic test variable) is shown as it is.
#include <string>

namespace hullopt::io {

/// The variable's name for a title: "LCF", "L/B", "transom immersion".
std::string DesignVariableName(const std::string& key);
/// The name with its unit for an axis: "LCF [% L]", "L/B [-]", "spacing [m]".
std::string DesignVariableAxisLabel(const std::string& key);

}  // namespace hullopt::io
