#include "app/design_resolution_check.h"

#include <stdexcept>

#include "evaluation/design_resolution_check.h"

#include "io/formats/input_error.h"

namespace hullopt::app {

void CheckDesignResolution(const io::ResolutionCheckConfig& check, const std::vector<sk::WaveSpectrum>& spectra,
                           const std::vector<sk::PassengerPosition>& points, const sk::EvaluationOptions& options,
                           const eval::DesignCase& computed, double cs_override, const std::string& where,
                           io::EvaluatedDesign* design) {
  try {
    design->resolution = eval::CheckDesignResolution(computed, design->rao, design->evaluation, spectra, points,
                                                     options, check.factor, check.options, cs_override);
  } catch (const eval::InputError& e) {
    throw io::InputError(where + ": " + e.what());
  }
  if (!design->resolution->converged)
    design->rao.warnings.push_back("resolution check: " + design->resolution->warning);
}

}  // namespace hullopt::app
