#pragma once
// The ship-motion solver as the RAO model of the Cs fit (optimizer/cs_calibration.h).
#include <string>
#include <vector>

#include "evaluation/design_case.h"
#include "optimizer/cs_calibration.h"

namespace hullopt::eval {

/// The time-domain strip method for the cases of one hull (local indices 0..cases-1; each case's Fn sets the
/// speed of `base`): the strip kernels do not depend on Cs, so they are built once per case and each model call
/// is a 2×2 solve per measured frequency. `warnings` (optional) receives the cases outside the method's validity
/// range (sk::ValidityWarnings). Throws InputError as BuildDesignKernel.
opt::CsRaoModel StripSolverCsModel(const DesignCase& base, const std::vector<opt::CalibrationCase>& cases,
                                   std::vector<std::string>* warnings = nullptr);

/// One hull's model and the global indices of its cases.
struct CsModelPart {
  opt::CsRaoModel model;
  std::vector<int> cases;
};
/// The model over all cases (global indices) that routes each case to its hull's part.
opt::CsRaoModel CombineCsModels(std::vector<CsModelPart> parts);

}  // namespace hullopt::eval
