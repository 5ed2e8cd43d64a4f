#pragma once
// Time marching of one water strip (docs/ship-motions.md; the stage between strip_operators.h and
// strip_kernel_builder.h): given the prescribed normal velocity at the collocation points step by step, the
// source strengths, the strip's vertical momentum and the sectional force.
//
// Force. The vertical hydrodynamic force per unit length on the section is taken as the rate of change of the
// vertical momentum of the strip's disturbance flow,
//   f_n = dI/dt,   I = ρ ∫_{S(t)} φ n_z dl   (n into the fluid),
// discretised by the second-order backward difference f_n = (3 I_n − 4 I_{n−1} + I_{n−2}) / (2 dt) (with
// end rows of their own when the steps are cell faces: StripOperators::ForceStencil), with I = 0 before the
// first step (the water is at rest until the bow enters). For a section that does not
// change, this equals the pressure integral −ρ ∫ φ_t n_z dl (n into the body) exactly. For a section that
// changes shape as the hull passes through the strip the two differ by a boundary-transport term linear in
// the motion; the momentum form is the one consistent with slender-body theory (it is what yields the −U
// dA33/dx-type terms and the transom term) and with the neglected interaction between the steady displacement
// flow and the unsteady potential; see docs/theory.md, "Sectional force in a strip whose section changes".
// Operators built for SectionalForce::kPressure give the reference paper's written form instead, the
// fixed-point pressure integral ρ∫φ_t n_z dl on the fluid side: dI/dt minus the moving contour's transport term
// (StripOperators::TransportCurrent).
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "seakeeping/strip/strip_operators.h"

namespace hullopt::sk {

class StripMarcher {
 public:
  /// Keeps a reference to `ops`, which must outlive the marcher.
  explicit StripMarcher(const StripOperators& ops);

  /// Steps taken so far (the next Advance computes step Step()).
  int Step() const { return static_cast<int>(sources_.size()); }
  /// Force f_n [N/m] that Advance(V) would return, without advancing (f is affine in V: callers coupling the
  /// body motion implicitly evaluate it at two velocities).
  double Peek(const Eigen::VectorXd& normal_velocity) const;
  /// Advances one step with the normal velocity V_n [m/s] at the collocation points of step n (size
  /// ops.PanelCount(n), positive into the fluid). Returns f_n [N/m], positive up. Throws std::out_of_range
  /// past the last step and std::invalid_argument for a wrong size.
  double Advance(const Eigen::VectorXd& normal_velocity);

  const std::vector<Eigen::VectorXd>& Sources() const { return sources_; }  ///< σ_n [m/s]
  const std::vector<double>& Momentum() const { return momentum_; }         ///< I_n [kg/s]

 private:
  struct Pending {
    Eigen::VectorXd sigma;
    double momentum = 0, force = 0;
  };
  Pending Compute(const Eigen::VectorXd& v) const;
  void PrepareHistory();
  const StripOperators& ops_;
  std::vector<Eigen::VectorXd> sources_;
  std::vector<double> momentum_;
  Eigen::VectorXd history_rhs_;  // Σ_{k<n} Memory(n, k) σ_k for the next step n
  double history_momentum_ = 0;  // Σ_{k<n} MomentumMemory(n, k) σ_k
  double history_transport_ = 0;  // pressure form: Σ_{k<n} TransportMemory(n, k) σ_k
};

}  // namespace hullopt::sk
