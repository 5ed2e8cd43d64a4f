#pragma once
// The ship-motion solver as the RAO model of the Cs fit (calibration/fit/cs_calibration.h).
#include <string>
#include <vector>

#include "evaluation/design_case.h"
#include "calibration/fit/cs_calibration.h"

namespace hullopt::calib {

/// The time-domain strip method for the cases of one hull (local indices 0..cases-1; each case's Fn sets the
/// speed of `base`): the strip kernels do not depend on Cs, so they are built once per case and each model call
/// is a 2×2 solve per measured frequency. `warnings` (optional) receives the cases outside the method's validity
/// range (sk::ValidityWarnings). Throws io::InputError as eval::BuildDesignKernel.
CsRaoModel StripSolverCsModel(const eval::DesignCase& base, const std::vector<opt::CalibrationCase>& cases,
                                   std::vector<std::string>* warnings = nullptr);

/// One hull's model and the global indices of its cases.
struct CsModelPart {
  CsRaoModel model;
  std::vector<int> cases;
};
/// The model over all cases (global indices) that routes each case to its hull's part.
CsRaoModel CombineCsModels(std::vector<CsModelPart> parts);

}  // namespace hullopt::calib
