#pragma once
// The parametric hull generator: DesignVariables -> faired HullForm at the requested displacement.
//
// Steps (docs/hull-generator.md, 'Generator (parametric_hull/hull_generator.h)'): the waterplane curve from
// Cwp and LCF and the sectional area curve from Cp and LCB (form_curve.h); at every station the local draught
// follows from the area and waterline breadth at a section area coefficient that rises from Cm at midships
// towards the ends (keel_rise); the section family honours breadth, draught and area exactly. Discretisation
// errors of the integrated hull are removed by re-targeting Cp, Cwp, LCB, LCF on the hull's own hydrostatics
// (a few fixed-point passes), then all axes are scaled by (∇_target/∇)^(1/3) with ∇ from hydrostatics.h's
// quadrature, so the displacement is met to round-off. Multihulls: catamaran/SWATH = one demihull at y_centre
// = spacing/2 (mirror pair), displacement split equally; trihull = main hull + outrigger pair over the aft
// outrigger_length_ratio of L, with the Table 1 coefficients met by main hull and outriggers together.
#include "parametric_hull/design_variables.h"
#include "parametric_hull/hull_form.h"

namespace hullopt::hull {

/// Generates the hull. Throws std::invalid_argument for out-of-range variables (the IsValid message) and
/// std::domain_error for a combination the families cannot meet (names the variables and the rule).
HullForm GenerateHull(const DesignVariables& dv);

}  // namespace hullopt::hull
