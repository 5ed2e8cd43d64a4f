#pragma once
// The hydrodynamic (disturbance-potential) force on every strip, advanced one time step at a time, for the
// time-marching path (2a). Two interchangeable implementations: the convolution of a precomputed StripKernel
// (KernelStripForceModel, here) and a direct marching strip solver (the transient Green-function solver
// wrapped to this interface), so that the ship equations can be checked against either.
//
// Picture: N strips fixed in space hold, at any instant, the hull sections of steps 0 (bow) .. N−1 (stern).
// Each call to Advance moves time on by one step Δt = Δx/U: every strip moves on to the next step, a fresh
// strip (at rest, never disturbed) enters at the bow and the one past the stern leaves.
#include <Eigen/Dense>
#include <vector>

#include "seakeeping/green/panel.h"
#include "seakeeping/strip/strip_kernel.h"

namespace hullopt::sk {

class StripForceModel {
 public:
  virtual ~StripForceModel() = default;
  /// Number of steps (stations) a strip passes through while the hull is in it.
  virtual int Steps() const = 0;
  /// Panels of the mean wetted section(s) held at step n (the same for every strip).
  virtual const std::vector<Panel>& PanelsAt(int n) const = 0;
  /// Calm water: forget all history, as if every strip had only ever seen zero normal velocity.
  virtual void Reset() = 0;
  /// One time step. normal_velocity[n] [m/s]: the normal velocity (body − incident wave) · n, positive into
  /// the fluid, at the collocation points of the strip now at step n (size PanelsAt(n).size()). Writes
  /// (*force_n)[n] [N/m], the vertical disturbance-potential force per unit length on the section at step n.
  virtual void Advance(const std::vector<Eigen::VectorXd>& normal_velocity, std::vector<double>* force_n) = 0;
  /// Re-solves the step just taken (same time, same history) with revised normal velocities, which replace
  /// the ones recorded for this step. Lets the marcher iterate the acceleration of the current step.
  virtual void Revise(const std::vector<Eigen::VectorXd>& normal_velocity, std::vector<double>* force_n) = 0;
};

/// f_n = Σ_{m ≤ n} force[n][m] · V_m(t − (n − m)Δt) with the normal-velocity history kept in a ring buffer.
/// O(N² P / 2) per step. The kernel must outlive the model.
class KernelStripForceModel final : public StripForceModel {
 public:
  explicit KernelStripForceModel(const StripKernel& kernel);
  int Steps() const override { return kernel_->Steps(); }
  const std::vector<Panel>& PanelsAt(int n) const override { return kernel_->panels[n]; }
  void Reset() override;
  void Advance(const std::vector<Eigen::VectorXd>& normal_velocity, std::vector<double>* force_n) override;
  void Revise(const std::vector<Eigen::VectorXd>& normal_velocity, std::vector<double>* force_n) override;

 private:
  void Store(const std::vector<Eigen::VectorXd>& normal_velocity);
  const StripKernel* kernel_;
  std::vector<std::vector<Eigen::VectorXd>> history_;  // [time slot mod N][step]
  long steps_done_ = 0;
  std::vector<double> memory_force_;  // Σ_{m < n} part of the step just taken
};

}  // namespace hullopt::sk
