#pragma once
// StripForceModel over the direct time marching of every strip (StripMarcher on shared StripOperators), the
// swap-in alternative to the kernel convolution: the same ship equations marched against the strip solver
// itself, which checks the kernel reduction end to end.
//
// The strip now at step n is a StripMarcher that has taken n steps. Advance first commits the velocities of
// the previous time step (StripMarcher::Advance), then evaluates the new step with StripMarcher::Peek (affine
// in V, not committed); Revise re-evaluates with Peek. A new strip enters at the bow every step.
#include <deque>
#include <memory>

#include "seakeeping/strip/strip_force_model.h"
#include "seakeeping/strip/strip_marcher.h"
#include "seakeeping/strip/strip_operators.h"

namespace hullopt::sk {

class MarchingStripForceModel final : public StripForceModel {
 public:
  /// ops must outlive the model.
  explicit MarchingStripForceModel(const StripOperators& ops);
  int Steps() const override { return ops_->Steps(); }
  const std::vector<Panel>& PanelsAt(int n) const override { return ops_->PanelsAt(n); }
  void Reset() override;
  void Advance(const std::vector<Eigen::VectorXd>& normal_velocity, std::vector<double>* force_n) override;
  void Revise(const std::vector<Eigen::VectorXd>& normal_velocity, std::vector<double>* force_n) override;

 private:
  const StripOperators* ops_;
  std::deque<std::unique_ptr<StripMarcher>> strips_;  // strips_[n]: the strip now at step n
  std::vector<Eigen::VectorXd> pending_;              // velocities of the current step, not yet committed
};

}  // namespace hullopt::sk
