#include "evaluation/design_resolution_check.h"

#include <stdexcept>
#include <string>

#include "evaluation/input_error.h"

namespace hullopt::eval {

sk::ResolutionCheck CheckDesignResolution(const DesignCase& design, const sk::RaoTable& coarse,
                                          const sk::DesignEvaluation& coarse_eval,
                                          const std::vector<sk::WaveSpectrum>& spectra,
                                          const std::vector<sk::PassengerPosition>& points,
                                          const sk::EvaluationOptions& options, int factor,
                                          const sk::ResolutionCheckOptions& check, double cs_override) {
  DesignCase fine = design;
  fine.solver.rao.sections *= factor;
  fine.solver.rao.panels *= factor;
  fine.solver.grid.enabled = false;  // the coarse table's own (possibly refined) grid, so the two compare
  if (fine.solver.rao.sections > kMaxCheckSections || fine.solver.rao.panels > kMaxCheckPanels)
    throw InputError("design '" + design.name + "': resolution_check.factor " + std::to_string(factor) +
                     " asks for " + std::to_string(fine.solver.rao.sections) + " sections x " +
                     std::to_string(fine.solver.rao.panels) + " panels, beyond the solver's " +
                     std::to_string(kMaxCheckSections) + " x " + std::to_string(kMaxCheckPanels));
  const sk::RaoTable fine_rao = ComputeDesignRaos(fine, coarse.omega_rad_s, cs_override);
  sk::DesignEvaluation fine_eval;
  try {
    fine_eval = sk::EvaluateDesign(fine_rao, design.Extent(), spectra, points, options);
  } catch (const std::exception& e) {
    throw InputError("design '" + design.name + "' at the check's resolution: " + e.what());
  }
  return sk::CompareResolutions(coarse, fine_rao, coarse_eval, fine_eval, design.solver.rao.sections,
                                design.solver.rao.panels, fine.solver.rao.sections, fine.solver.rao.panels, check);
}

}  // namespace hullopt::eval
