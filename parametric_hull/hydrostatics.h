#pragma once
// Hydrostatics of any HullForm (generated or read) at its design draught, upright and at rest.
//
// Conventions (docs/conventions.md): L is the waterline length of the main body (HullForm::length_m if set,
// else the span of its wetted stations); B the largest breadth of the main body below the waterline; T the
// design draught above the baseline. Volumes, areas and moments are totals over ALL bodies (mirror pairs
// counted twice). Form coefficients refer to one reference hull: they divide the totals by the number of
// reference hulls N (bodies that are not "outrigger", mirror pairs counted twice: 1 monohull and trihull, 2
// catamaran and SWATH), so a catamaran's coefficients are those of one demihull and a trihull's include its
// outriggers:
//   Cb = ∇/(N L B T), Cm = A_M/(N B T), Cp = ∇/(L A_M), Cwp = A_wp/(N L B), Cvp = ∇/(A_wp T),
// with A_M the total section area at midships (x = x_AP + L/2, x_AP the first wetted station of the main
// body). LCB, LCF in % of L from midships, positive forward.
//
// Quadrature: section integrals are exact for the polyline contours (section_geometry.h); along x the
// LongitudinalWeights rule over each body's own stations. The generator scales to its displacement with the
// same rules, so targets are met to round-off in this measure.
#include "parametric_hull/hull_form.h"

namespace hullopt::hull {

struct Hydrostatics {
  double L_m = 0.0;              ///< [m] waterline length of the main body
  double B_m = 0.0;              ///< [m] max breadth of the main body below the waterline
  double T_m = 0.0;              ///< [m] draught
  int reference_hulls = 1;       ///< N in the coefficients above
  double volume_m3 = 0.0;        ///< [m^3] displaced volume, all bodies
  double displacement_kg = 0.0;  ///< [kg] rho * volume
  double displacement_t = 0.0;   ///< [t] displacement_kg / 1000
  double lcb_m_from_ap = 0.0;    ///< [m] longitudinal centre of buoyancy, x from AP
  double vcb_m = 0.0;            ///< [m] KB: vertical centre of buoyancy above the baseline
  double awp_m2 = 0.0;           ///< [m^2] waterplane area, all bodies
  double lcf_m_from_ap = 0.0;    ///< [m] longitudinal centre of flotation, x from AP
  double midship_area_m2 = 0.0;  ///< [m^2] A_M: section area at midships, all bodies
  double i_l_m4 = 0.0;           ///< [m^4] waterplane second moment about the transverse axis through the LCF
  double i_t_m4 = 0.0;           ///< [m^4] waterplane second moment about the ship centreline (x axis)
  double bm_l_m = 0.0;           ///< [m] longitudinal metacentric radius I_L/∇
  double bm_t_m = 0.0;           ///< [m] transverse metacentric radius I_T/∇
  double kg_m = 0.0;             ///< [m] KG used for GM (as given)
  double gm_l_m = 0.0;           ///< [m] KB + BM_L - KG
  double gm_t_m = 0.0;           ///< [m] KB + BM_T - KG
  double wetted_surface_m2 =
      0.0;              ///< [m^2] ∫ wetted girth dx, all bodies (girth of the sections; neglects the
                        ///< longitudinal slope of the surface, a few per mille for slender hulls)
  double x_ap_m = 0.0;  ///< [m] x of the aft end of the main body's waterline (AP)
  double Cb = 0.0, Cp = 0.0, Cm = 0.0, Cwp = 0.0, Cvp = 0.0;
  double LCB_pct_L = 0.0;  ///< [% L] (LCB - midships)/L * 100, positive forward
  double LCF_pct_L = 0.0;  ///< [% L] (LCF - midships)/L * 100, positive forward
};

/// Hydrostatics of `hull` at hull.draught_m in water of density rho_kg_m3 [kg/m^3]; kg_m [m] is the vertical
/// centre of gravity above the baseline for GM. Throws std::invalid_argument for a hull without stations,
/// non-positive draught or density, and std::domain_error if the hull displaces no water or has no
/// waterplane.
Hydrostatics ComputeHydrostatics(const HullForm& hull, double rho_kg_m3 = 1025.0, double kg_m = 0.0);

/// Displaced volume [m^3] of all bodies, by the same rules as ComputeHydrostatics (cheaper; for scaling).
double DisplacedVolume(const HullForm& hull);

/// Number of reference hulls N (see above).
int ReferenceHullCount(const HullForm& hull);

}  // namespace hullopt::hull
