#pragma once
// Physical plausibility of a hull and its mass properties, one rule per quantity, the same for generated and
// read hulls. A rule either refuses (the input cannot describe a floating hull, or almost certainly carries a
// unit error) or warns (a designer may legitimately go there; the config has a key to accept it). The rules
// and their limits are listed in docs/bad-inputs.md.
#include <string>
#include <vector>

#include "parametric_hull/hull_form.h"
#include "parametric_hull/hydrostatics.h"

namespace hullopt::hull {

struct PlausibilityFinding {
  std::string quantity;  ///< e.g. "Cb", "mass_kg", "spacing"
  std::string message;   ///< the rule and the numbers
  bool refuse = true;    ///< false: a warning
};

/// Limits of the rules (defaults documented in docs/bad-inputs.md).
struct PlausibilityLimits {
  /// |mass / displaced mass - 1| beyond which the mass is refused: the hull would float at another draught.
  double mass_tolerance = 0.02;
  /// L/T and L/B above these mean the stations and the draught/beam are in different units (mm vs m).
  double max_L_over_T = 200.0;
  double max_L_over_B = 100.0;
  /// A length override must lie within this factor of the span of the wetted stations.
  double length_override_factor = 1.5;
  /// Pitch radius of gyration: above 0.5 L no mass distribution within the hull's length can give it; below
  /// 0.1 L the mass would be concentrated at the CG. Outside [0.15, 0.35] L is unusual (warning).
  double kyy_min_over_L = 0.1, kyy_max_over_L = 0.5;
  double kyy_usual_min_over_L = 0.15, kyy_usual_max_over_L = 0.35;
  /// KG above the baseline: up to this many draughts plus the half length is refused beyond (a centre of
  /// gravity far above any superstructure).
  double kg_max_over_L = 0.5;
};

/// Form coefficients in (0, 1] and consistent (Cb <= Cm, Cb <= Cp, non-SWATH Cvp <= 1), LCB and LCF inside
/// the waterline length, L/T and L/B plausible for the units, a length override close to the stations' span,
/// demihulls that do not overlap (centre spacing greater than the demihull beam). The clearance is in the
/// message.
std::vector<PlausibilityFinding> CheckHullPlausibility(const HullForm& hull, const Hydrostatics& hs,
                                                       const PlausibilityLimits& limits = {});

/// Mass within limits.mass_tolerance of the displaced mass (refused beyond, or a warning when accept_mass is
/// set), KG and k_yy in physical ranges for the hull's size.
std::vector<PlausibilityFinding> CheckMassPlausibility(const MassProperties& mass, const Hydrostatics& hs,
                                                       bool accept_mass_mismatch,
                                                       const PlausibilityLimits& limits = {});

/// Demihull clearance [m]: centre spacing minus the demihull beam (> 0 when the demihulls are apart); 0 for a
/// hull without a second demihull.
double DemihullClearance(const HullForm& hull, const Hydrostatics& hs);

}  // namespace hullopt::hull
