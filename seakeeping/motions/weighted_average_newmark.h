#pragma once
// Trapezoid (Newmark average-acceleration) kinematics with the paper's weighted average of the hydrodynamic
// and the extrapolated acceleration (docs/theory.md, 'Weighted-average acceleration (averaging method)').
// Step K → K+1:
//   â⁰      = 2 a_K − a_{K−1}                                 (linear extrapolation; a_0 at the first step)
//   pass p:  v = v_K + Δt/2 (a_K + âᵖ),  x = x_K + Δt v_K + Δt²/4 (a_K + âᵖ)
//            âᵖ⁺¹ = w F(x, v)/M + (1 − w) âᵖ                  (w = hydrodynamic fraction)
// Let the force respond to the trial acceleration as F ≈ F₀ − A â (A: the instantaneous added mass of the
// kernel). Then âᵖ⁺¹ = w F₀/M + ρ âᵖ with ρ = 1 − w(1 + A/M):
// - Passes repeated until â settles (at most max_passes): a fixed-point iteration, convergent for |ρ| < 1, whose
//   limit is the implicit trapezoid solution whatever w (unconditionally stable; steady-state error against the
//   exact solution only the trapezoid's frequency warp, Ω = (2/Δt) tan(ωΔt/2) ≈ ω (1 + (ωΔt)²/12)).
// - One pass (the paper's scheme as written): a_{K+1} = w F₀/M + ρ (2 a_K − a_{K−1}). Its parasitic root solves
//   z² − 2ρ z + ρ = 0 and stays inside the unit circle for −1/3 < ρ < 1, a narrower range than |ρ| < 1 (the
//   extrapolation doubles a_K). Its steady state carries the extrapolation error 2 a_K − a_{K−1} − a_{K+1}
//   ≈ (ωΔt)² a amplified by ρ/(w(1 + A/M)): 6% at ωΔt = 0.13, w = 0.2, A/M small.
// The plain explicit update (w = 1, one pass) is unstable once A/M > 1/3.
#include "seakeeping/motions/time_scheme.h"

#include <string>

namespace hullopt::sk {

struct WeightedAverageParameters {
  double hydrodynamic_fraction = 0.2;  ///< w [-], 0 < w <= 1 (paper: 0.2–0.4 acceptable)
  int max_passes = 200;                ///< passes per step, >= 1
  double pass_tolerance = 1e-7;  ///< stop the passes when the acceleration changes by less than this fraction of
                                 ///< its running maximum, > 0
  bool IsValid(std::string* error) const;
};

class WeightedAverageNewmark final : public TimeScheme {
 public:
  /// Throws std::invalid_argument for invalid parameters.
  explicit WeightedAverageNewmark(const WeightedAverageParameters& parameters);
  void Restart() override;
  void Step(double dt_s, const TrialAcceleration& hull_acceleration, MarchingState* state) override;

 private:
  WeightedAverageParameters p_;
  DofPair a_scale_{};  // running max |a| for the pass tolerance
};

}  // namespace hullopt::sk
