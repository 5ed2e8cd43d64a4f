#include "app/design_resolution_check.h"

#include <stdexcept>

#include "io/input_error.h"

namespace hullopt::app {

void CheckDesignResolution(const io::ResolutionCheckConfig& check, const std::vector<sk::WaveSpectrum>& spectra,
                           const std::vector<sk::PassengerPosition>& points, const sk::EvaluationOptions& options,
                           const eval::DesignCase& computed, double cs_override, const std::string& where,
                           io::EvaluatedDesign* design) {
  eval::DesignCase fine = computed;
  fine.solver.rao.sections *= check.factor;
  fine.solver.rao.panels *= check.factor;
  if (fine.solver.rao.sections > 400 || fine.solver.rao.panels > 100)
    throw io::InputError(where + ": design '" + design->name + "': resolution_check.factor " +
                         std::to_string(check.factor) + " asks for " + std::to_string(fine.solver.rao.sections) +
                         " sections x " + std::to_string(fine.solver.rao.panels) +
                         " panels, beyond the solver's 400 x 100");
  const sk::RaoTable fine_rao = eval::ComputeDesignRaos(fine, design->rao.omega_rad_s, cs_override);
  sk::DesignEvaluation fine_eval;
  try {
    fine_eval = sk::EvaluateDesign(fine_rao, design->hull, spectra, points, options);
  } catch (const std::exception& e) {
    throw io::InputError(where + ": design '" + design->name + "' at the check's resolution: " + e.what());
  }
  design->resolution = sk::CompareResolutions(design->rao, fine_rao, design->evaluation, fine_eval,
                                              computed.solver.rao.sections, computed.solver.rao.panels,
                                              fine.solver.rao.sections, fine.solver.rao.panels, check.options);
  if (!design->resolution->converged)
    design->rao.warnings.push_back("resolution check: " + design->resolution->warning);
}

}  // namespace hullopt::app
