#pragma once
// The hydrostatic pressure deficit of a dry transom (Doctors & Day 1997; Michlet's "Rh"): at rest the water
// pressure on the immersed transom face pushes the hull forward; once the transom runs dry at speed that push
// is lost, which adds R_h = ρ g ∫_transom (T - z) dA to the resistance. It pairs with the open aft end of the
// Michell integral (michell_integral.h).
#include "parametric_hull/hull_form.h"

namespace hullopt::res {

struct TransomGeometry {
  double area_m2 = 0.0;          ///< [m^2] immersed transom area at rest, all bodies
  double first_moment_m3 = 0.0;  ///< [m^3] ∫ (T - z) dA over it, all bodies
  double max_depth_m = 0.0;      ///< [m] deepest transom immersion T - z_keel (0 without a transom)
};

/// The immersed part of the aft station of every body (mirror pairs counted twice).
TransomGeometry ComputeTransomGeometry(const hull::HullForm& hull);

/// Transom Froude number U / √(g T_transom) above which the transom is taken to run clean (dry). Doctors'
/// tank data (Doctors 2006, "A study of the transom ventilation problem") put full ventilation near
/// F_T ≈ 4–5; below this the dry-transom model is flagged, not changed.
constexpr double kDryTransomFroude = 4.0;

}  // namespace hullopt::res
