#pragma once
// The rigid ship in head seas on top of one strip kernel: everything the two solution paths (periodic steady
// state and time marching) share. Heave and pitch only, origin at the CG, x forward, heave x3 up, pitch x5
// bow-down (docs/conventions.md). The section held at step n of a strip lies at x_n = x_m[n] − LCG.
//
// Per unit length at x_n the hull feels (docs/theory.md, '2.5D (2D+t) theory'; paper §2):
//   f_n = f_n^kernel                      disturbance potential (radiation + diffraction), from the strip
//   kernel
//       − ρ g B_n s_n                      linear hydrostatic restoring, s = x3 − x x5
//       + ρ g Σ_j G_n(k_j) ζ_j(x_n, t)     Froude–Krylov, G_n(k) = −∮ e^{kz} n_z dl over the mean wetted
//       panels − ½ Cs ρ U B_n (v_n − ζ_t(x_n))    the paper's sectional damping D = ½ Cs ρ U v B against the
//       velocity
//                                           relative to the local water surface
// with v_n = ẋ3 − x_n ẋ5 + U x5 the section's vertical velocity seen in the earth-fixed strip. The kernel
// input on panel i is V_i = n_z,i (v_n − w(x_n, z_i, t)). Hull force F3 = Σ f_n w_n, moment F5 = −Σ x_n f_n
// w_n (w_n = StripKernel::Weight(n): Δx, or Δx/2 at the end faces of StationLayout::kCellFaces), and M ẍ3 =
// F3, I5 ẍ5 = F5 with only the ship's own mass and inertia on the right (paper §2). Static equilibrium is
// assumed (weight = buoyancy, LCG over LCB); the hydrostatic pitch stiffness is the strip sum ρ g Σ B x² Δx
// (the small ρ g ∇ (z_B − z_G) term of a 3D C55 is not in a strip model).
#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

#include "parametric_hull/hull_form.h"
#include "seakeeping/strip/strip_kernel.h"

namespace hullopt::sk {

struct MotionOptions {
  double damping_cs = 0.0;  ///< Cs [-] of the sectional damping D = ½ Cs ρ U v B (paper: 0–0.15)
  std::string hull_name;    ///< names the hull in error messages only
  /// Cs finite and >= 0.
  bool IsValid(std::string* error) const;
};

/// Mean wetted section held at one step of the strip.
struct StationData {
  double x_cg_m = 0.0;     ///< [m] station forward of the CG
  double weight_m = 0.0;   ///< [m] weight of the station in the hull sums (StripKernel::Weight)
  double beam_m = 0.0;     ///< [m] waterline beam of all bodies in the strip, −Σ Δy over the panels
  Eigen::VectorXd nz;      ///< [-] vertical component of the unit normal (into the fluid) per panel
  Eigen::VectorXd z_mid;   ///< [m] collocation-point depth per panel (≤ 0)
  Eigen::VectorXd dy;      ///< [m] y2 − y1 per panel (n_z dl integrates to dy)
  Eigen::VectorXd z1, z2;  ///< [m] panel end depths
  /// G(k) = −Σ_i ∫ e^{kz} n_z dl [m]: the Froude–Krylov width, exact for straight panels; G(0) = B.
  double FroudeKrylovWidth(double k_rad_m) const;
};

class HeadSeaShipModel {
 public:
  /// kernel must outlive the model. Throws std::invalid_argument naming the rule for an inconsistent kernel
  /// (speed, dx, dt = dx/U, ρ, g, force shapes), non-positive mass or radius of gyration, or invalid options.
  HeadSeaShipModel(const StripKernel& kernel, const hull::MassProperties& mass, const MotionOptions& options);

  const StripKernel& kernel() const { return *kernel_; }
  const std::vector<StationData>& stations() const { return stations_; }
  const MotionOptions& options() const { return options_; }
  int Steps() const { return static_cast<int>(stations_.size()); }
  double speed() const { return kernel_->speed_m_s; }
  double rho() const { return kernel_->rho_kg_m3; }
  double g() const { return kernel_->g_m_s2; }
  double dx() const { return kernel_->dx_m; }
  double dt() const { return kernel_->dt_s; }
  double mass() const { return mass_kg_; }                 ///< [kg] M
  double pitch_inertia() const { return inertia_kg_m2_; }  ///< [kg m²] I5 = M k_yy²
  /// ½ Cs ρ U [kg/m²/s]: the damping force per unit length is −DampingFactor()·B·v [N/m].
  double DampingFactor() const { return 0.5 * options_.damping_cs * rho() * speed(); }

  /// Throws std::domain_error "hull '<name>': non-finite <what> at ω = .. rad/s (ω_e = .. rad/s)".
  [[noreturn]] void ReportNonFinite(const std::string& what, double omega_rad_s) const;

 private:
  const StripKernel* kernel_;
  MotionOptions options_;
  double mass_kg_ = 0.0;
  double inertia_kg_m2_ = 0.0;
  std::vector<StationData> stations_;
};

}  // namespace hullopt::sk
