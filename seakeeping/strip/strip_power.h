#pragma once
// The power a strip's moving contour delivers to the water, and the potential of a march's state at any point
// of the fluid (docs/ship-motions.md, "Calm water and the running attitude": the 2D+t wave resistance).
//
// A hull moving at U through strips fixed in space pushes on each strip's water with the dynamic pressure
// p = −ρ φ_t over its contour, whose points move into the fluid at the normal speed W_n. The power per unit
// strip length is P(t) = ∫_S p W_n dl. Every strip repeats the same history, so the power the hull spends on
// the water at any instant is U ∫ P dt over one strip's life, and the wave-making resistance is
//   R = ∫ P dt = Σ_n P_n w_n / U        (w_n the station weights, dt = dx/U).
// The hydrostatic part of the pressure is left out: over a closed hull it does no work, and at a dry transom
// its work is the missing hydrostatic force on the transom, a separate term (resistance/dry_transom.h).
//
// φ_t is the time derivative at a FIXED point of the contour, on the fluid side. A point of the step-n contour
// lies in the fluid at the earlier steps where the section grows (W_n > 0) and at the later steps where it
// shrinks (W_n < 0), so φ_t is the one-sided second-order difference towards that side, of the march's own
// potential at that point (the potential of the source layer inside a contour is not the fluid's).
//
// The march's potential (strip_operators.h) at a point p and time t_m, from the sources σ_k of steps k <= m:
//   φ_m(p) = Σ_j σ_{m,j} R_j(p) − Σ_{k<=m} Σ_j σ_{k,j} (1/2π) ∫_{interval k, cut at t_m} ∫_{panel k,j} G~ ds dτ,
// R_j the Rankine pair (1/2π)∫(ln r − ln r′) ds; both from closed forms (rankine_panel.h, memory_influence.h),
// an evaluation independent of the operators' batched tables (the strip momentum ρ∫φ n_z dl they give is the
// check, tests/verification/test_strip_power.cpp).
//
// What it holds and does not: the linear free surface and the linear pressure of the strips; the quadratic
// pressure and the flow's own longitudinal velocity are left out, as in the steady force.
#include <Eigen/Dense>
#include <vector>

#include "seakeeping/strip/contour_motion.h"
#include "seakeeping/strip/strip_operators.h"

namespace hullopt::sk {

/// φ_m [m²/s] of a march (sources per step as StripMarcher::Sources(), on the panels of ops.PanelsAt) at the
/// points (y[i], z[i]) [m], z < 0. A point on a panel of step m gets the layer's (continuous) potential.
/// Throws std::invalid_argument for m outside the march or a point on or above z = 0.
std::vector<double> MarchPotential(const StripOperators& ops, const std::vector<Eigen::VectorXd>& sources, int m,
                                   const std::vector<double>& y, const std::vector<double>& z);

/// P_n [W/m] at every step of a completed march: −ρ ∫ φ_t W_n dl over the contour of step n (all its panels),
/// W_n from motions[n] (one value per panel of ops.FullPanelsAt(n)), ∫ by two-point Gauss-Legendre on each
/// panel. φ_t by the one-sided second-order difference towards the side where the point is in the fluid (first
/// order where only one neighbouring step exists on that side). Empty steps give 0.
std::vector<double> StripPower(const StripOperators& ops, const std::vector<Eigen::VectorXd>& sources,
                               const std::vector<ContourMotion>& motions);

}  // namespace hullopt::sk
