#pragma once
// hydrostatics.json of `hullopt hull` (docs/file-formats.md): L_m, B_m, T_m, volume_m3, displacement_t, Cb,
// Cp, Cm, Cwp, Cvp, LCB_pct_L, LCF_pct_L, Fr (coefficients per reference hull, see
// parametric_hull/hydrostatics.h), for a multihull also hulls and spacing_m; plus the other hydrostatic
// quantities with units in their names.
#include <optional>
#include <string>
#include <vector>

#include "parametric_hull/hull_form.h"
#include "parametric_hull/hydrostatics.h"
#include "parametric_hull/running_attitude.h"

namespace hullopt::io {

struct HydrostaticsReport {
  hull::Hydrostatics hs;
  double rho_kg_m3 = 1025.0;
  double g_m_s2 = 9.81;
  std::optional<double> speed_m_s;  ///< [m/s]; Fr is written as null without it
  std::vector<std::string> warnings;  ///< plausibility warnings, written as "warnings"
  /// Hydrostatics of the hull at its running attitude (written as "running_attitude" with the attitude),
  /// absent at even keel.
  std::optional<hull::Hydrostatics> running;
  hull::RunningAttitude attitude;
  /// What the generator changed from the config to build the hull (on_infeasible: nearest), one line each;
  /// written as "adjustments" (an empty list when nothing was changed).
  std::vector<std::string> adjustments;
};

/// Writes the JSON file; throws InputError if it cannot be written.
void WriteHydrostaticsJson(const std::string& path, const hull::HullForm& hull, const HydrostaticsReport& r);

}  // namespace hullopt::io
