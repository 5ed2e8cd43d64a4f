#pragma once
// Path 2a: heave and pitch marched in time over the strips with the paper's weighted average of the
// hydrodynamically derived and the extrapolated acceleration (theory notes §4.3).
//
// Step K → K+1 (Δt = Δx/U), trapezoid (Newmark average-acceleration) kinematics:
//   â⁰      = 2 a_K − a_{K−1}                                 (linear extrapolation; a_0 at the first step)
//   pass p:  v = v_K + Δt/2 (a_K + âᵖ),  x = x_K + Δt v_K + Δt²/4 (a_K + âᵖ)
//            F = hull force at t_{K+1} with that state and the wave (strip forces from a StripForceModel)
//            âᵖ⁺¹ = w F/M + (1 − w) âᵖ                        (w = hydrodynamic fraction)
// The kernel's instantaneous added-mass part makes the plain explicit update (w = 1) unstable once the added
// mass exceeds the ship's mass; the weighted average is stable for |1 − w(1 + A/M)| < 1 (theory notes §4.3).
// With max_passes = 1 this is the single-pass scheme as the paper describes it; its steady state carries an
// error ≈ (1 − w(1 + A/M))/w · (ω_e Δt)² (the extrapolation error, amplified: 6% at ω_e Δt = 0.13, w = 0.2,
// A/M small). By default the average is repeated within the step (the current step's strip solution revised)
// until the acceleration settles, so the result is the implicit trapezoid solution whatever w, whose error
// against the exact steady state is only the trapezoid's frequency warp (ω_e Δt)²/12.
#include <vector>

#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/motions/head_sea_wave.h"
#include "seakeeping/motions/rao_table.h"
#include "seakeeping/strip/strip_force_model.h"

namespace hullopt::sk {

struct MarchingOptions {
  double hydrodynamic_fraction = 0.2;  ///< w [-], 0 < w <= 1 (paper: 0.2–0.4 acceptable)
  double ramp_periods = 3.0;  ///< regular waves: half-cosine ramp-in of the wave [encounter periods], >= 0
  int fit_periods = 4;        ///< regular waves: Fourier fit over this many last periods, >= 1
  int max_periods = 400;      ///< regular waves: give up after this many periods, > ramp + fit
  double steady_tolerance = 1e-4;  ///< change of |ΔX3/A| + |ΔX5/(kA)| between successive fits, > 0
  int max_passes = 200;            ///< weighted-average passes per step, >= 1 (1: the paper's single pass)
  double pass_tolerance = 1e-7;    ///< stop the passes when the acceleration changes by less than this
                                   ///< fraction of its running maximum, > 0
  bool IsValid(std::string* error) const;
};

/// Motions sampled at every time step.
struct MotionTimeSeries {
  std::vector<double> t_s;           ///< [s]
  std::vector<double> heave_m;       ///< [m] x3, up
  std::vector<double> pitch_rad;     ///< [rad] x5, bow-down
  std::vector<double> wave_at_cg_m;  ///< [m] incident elevation at the CG (ramp included)
};

/// The marching state machine, for callers that need step-by-step access (transients, custom stopping).
class TimeMarcher {
 public:
  /// model and forces must outlive the marcher; forces must describe the same steps and panels as the model.
  TimeMarcher(const HeadSeaShipModel& model, StripForceModel& forces, const MarchingOptions& options);
  /// Rest in calm water at t = 0; the sea is ramped in over ramp_s [s] (0: switched on at once).
  void Start(const std::vector<WaveComponent>& sea, double ramp_s);
  /// One time step. Throws std::domain_error naming the hull if the motion becomes non-finite (unstable).
  void Step();
  double time_s() const { return t_; }
  double heave_m() const { return x_[0]; }
  double pitch_rad() const { return x_[1]; }
  double WaveAtCg() const;

 private:
  const HeadSeaShipModel& model_;
  StripForceModel& forces_;
  MarchingOptions options_;
  std::vector<WaveComponent> sea_;
  std::vector<double> k_, omega_e_;
  std::vector<std::vector<double>> fk_width_;  // [n][component] G_n(k_j)
  std::vector<Eigen::MatrixXd> ekz_;           // [n] panels × components, e^{k_j z_i}
  double ramp_s_ = 0.0, t_ = 0.0;
  long k_step_ = 0;
  double x_[2] = {0, 0}, v_[2] = {0, 0}, a_[2] = {0, 0}, a_prev_[2] = {0, 0};
  double a_scale_[2] = {0, 0};  // running max |a| for the pass tolerance
  std::vector<Eigen::VectorXd> velocity_;
  std::vector<double> kernel_force_;
};

/// Regular-wave RAOs by marching each frequency from rest to steady state and fitting amplitude and phase
/// over the last fit_periods periods. Throws std::invalid_argument for bad options or frequencies,
/// std::domain_error if a frequency does not settle within max_periods or diverges (naming hull and
/// frequency).
RaoTable SolveMarchingRaos(const HeadSeaShipModel& model, StripForceModel& forces,
                           const std::vector<double>& omega_rad_s, const MarchingOptions& options);

/// Time series in an irregular (or any) head sea given as components, from rest, for duration_s [s], with the
/// sea ramped in over ramp_s [s]. The interface for time-domain checks of spectral (MSI) results.
MotionTimeSeries MarchHeadSea(const HeadSeaShipModel& model, StripForceModel& forces,
                              const std::vector<WaveComponent>& sea, double duration_s, double ramp_s,
                              const MarchingOptions& options);

}  // namespace hullopt::sk
