#pragma once
// Path 2a: heave and pitch marched in time over the strips (docs/theory.md, 'Weighted-average
// acceleration (averaging method)'). This file holds the force model of a step: hydrostatics, Froude–Krylov and wave terms, the sectional damping and the strip forces of
// a StripForceModel, summed into the hull's heave and pitch accelerations at a trial state. How the trial
// states are chosen is the time scheme's business (time_scheme.h), picked by MarchingOptions::scheme from the
// registry (time_scheme_registry.h); Δt = Δx/U, the strip step.
#include <memory>
#include <vector>

#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/motions/head_sea_wave.h"
#include "seakeeping/motions/rao_table.h"
#include "seakeeping/motions/time_scheme.h"
#include "seakeeping/motions/time_scheme_registry.h"
#include "seakeeping/strip/strip_force_model.h"

namespace hullopt::sk {

struct MarchingOptions {
  TimeSchemeKind scheme = TimeSchemeKind::kWeightedAverageTrapezoid;  ///< the step kinematics (registry)
  double hydrodynamic_fraction = 0.2;  ///< w [-], 0 < w <= 1 (paper: 0.2–0.4 acceptable)
  double ramp_periods = 3.0;  ///< regular waves: half-cosine ramp-in of the wave [encounter periods], >= 0
  int fit_periods = 4;        ///< regular waves: Fourier fit over this many last periods, >= 1
  int max_periods = 400;      ///< regular waves: give up after this many periods, > ramp + fit
  double steady_tolerance = 1e-4;  ///< change of |ΔX3/A| + |ΔX5/(kA)| between successive fits, > 0
  int max_passes = 200;  ///< cap of weighted_average_trapezoid's passes per step, >= 1 (1: the same steps as
                         ///< paper_single_pass); paper_single_pass makes one pass whatever this says
  double pass_tolerance = 1e-7;    ///< stop the passes when the acceleration changes by less than this
                                   ///< fraction of its running maximum, > 0
  bool IsValid(std::string* error) const;
  /// The weighted-average scheme's parameters among these options.
  WeightedAverageParameters SchemeParameters() const;
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
  double heave_m() const { return state_.x[0]; }
  double pitch_rad() const { return state_.x[1]; }
  double WaveAtCg() const;

 private:
  /// The hull's accelerations (F3/M, F5/I_yy) at t_ with the trial state (x, v); trial 0 advances the strips.
  DofPair HullAcceleration(const DofPair& x, const DofPair& v, int trial);

  const HeadSeaShipModel& model_;
  StripForceModel& forces_;
  MarchingOptions options_;
  std::unique_ptr<TimeScheme> scheme_;
  std::vector<WaveComponent> sea_;
  std::vector<double> k_, omega_e_;
  std::vector<std::vector<double>> fk_width_;  // [n][component] G_n(k_j)
  std::vector<Eigen::MatrixXd> ekz_;           // [n] panels × components, e^{k_j z_i}
  double ramp_s_ = 0.0, t_ = 0.0;
  MarchingState state_;
  // Wave terms of the current step, fixed during its trials: Froude–Krylov force, rate of rise of the surface
  // and the orbital velocity at the collocation points.
  std::vector<double> fk_, surface_rate_;
  std::vector<Eigen::VectorXd> orbital_;
  std::vector<Eigen::VectorXd> velocity_;
  std::vector<double> kernel_force_, section_force_;
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
