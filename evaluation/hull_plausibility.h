#pragma once
// Applying the plausibility rules (parametric_hull/plausibility.h) to a hull or mass as it is loaded: a
// refusal becomes an InputError naming the source and the rule, a warning is returned for the outputs.
#include <string>
#include <vector>

#include "evaluation/validity_envelope.h"
#include "evaluation/water.h"
#include "parametric_hull/hull_form.h"
#include "parametric_hull/plausibility.h"

namespace hullopt::eval {

/// Hydrostatics of the hull, then the hull rules. `where` names the source ("file.csv", "config: key
/// 'hull.parametric'"). Throws InputError "where: rule" for the first refusal (also when the hull displaces
/// no water); returns the warnings.
std::vector<std::string> CheckHull(const hull::HullForm& hull, const std::string& where);

/// Throws InputError "where: rule" for the first refusal among findings; returns the warnings' messages.
std::vector<std::string> ApplyFindings(const std::vector<hull::PlausibilityFinding>& findings,
                                       const std::string& where);

/// The validity envelope (evaluation/validity_envelope.h) applied as ApplyFindings does: throws InputError
/// "where: key 'k': rule" for the first refusal; returns the warnings' messages.
std::vector<std::string> ApplyEnvelope(const std::vector<EnvelopeFinding>& findings, const std::string& where);

/// The envelope of one design's inputs, applied as ApplyEnvelope: water, hull and its hydrostatics at rest,
/// and where known (NaN speed or cs, null mass: not checked) the speed [m/s], Cs and mass.
std::vector<std::string> ApplyDesignEnvelope(const WaterOptions& water, double speed_m_s, double cs,
                                             const hull::HullForm& hull, const hull::Hydrostatics& hs,
                                             const hull::MassProperties* mass, const std::string& where);

}  // namespace hullopt::eval
