#pragma once
// The impulsive (infinite-frequency) limit of the strip kernel: φ = 0 on the mean free surface, as at the
// first instant of the transient problem (docs/theory.md, 'Impulsive limit (A∞)'). In each strip the
// disturbance potential follows the instantaneous normal velocity, φ = S A⁻¹ V (A: normal velocity of Rankine
// panels and their negative images, S: their potentials, collocation at panel midpoints), and the force per
// unit length is
//   f = ρ d/dt ∮ φ n_z dl   (p = −ρ φ_t on the body, force −∮ p n_z dl),
// taken along the strip: f_n(t) = ρ (Φ_n(t) − Φ_{n−1}(t − Δt))/Δt with Φ_n = q_n · V_n. This is slender-body
// (2D+t) theory without gravity waves in the strip: no radiation damping, only the momentum exchange with the
// varying sections (transom and changing added mass). It fills a StripKernel's force rows force[n][n] and
// force[n][n−1] only; it is a comparator and a stand-in, not the paper's method, which also carries the
// free-surface memory of the transient Green function.
#include "seakeeping/strip/strip_kernel.h"

namespace hullopt::sk {

/// Fills kernel->force (which must already hold the geometry: dx, dt, ρ, panels; see StripKernelGeometry).
/// Throws std::invalid_argument if the geometry is missing, std::domain_error if a section's Rankine system
/// is singular.
void FillImpulsiveStripKernel(StripKernel* kernel);

/// q [m per m/s]: ∮ φ n_z dl per unit normal velocity on each panel of one strip holding `panels`, with φ = 0
/// on z = 0. For a semicircle of radius R in heave (V = n_z), −ρ q·n_z is the added mass ρπR²/2.
Eigen::RowVectorXd ImpulsivePotentialIntegral(const std::vector<Panel>& panels);

}  // namespace hullopt::sk
