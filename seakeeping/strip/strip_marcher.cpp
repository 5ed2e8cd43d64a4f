#include "seakeeping/strip/strip_marcher.h"

#include <stdexcept>
#include <string>

namespace hullopt::sk {

StripMarcher::StripMarcher(const StripOperators& ops) : ops_(ops) { PrepareHistory(); }

void StripMarcher::PrepareHistory() {
  const int n = Step();
  if (n >= ops_.Steps()) return;
  history_rhs_ = Eigen::VectorXd::Zero(ops_.PanelCount(n));
  history_momentum_ = 0;
  history_transport_ = 0;
  const bool pressure = ops_.Force() == SectionalForce::kPressure;
  for (int k = 0; k < n; ++k) {
    if (sources_[k].size() == 0) continue;
    if (history_rhs_.size() > 0) history_rhs_ += ops_.Memory(n, k) * sources_[k];
    history_momentum_ += ops_.MomentumMemory(n, k).dot(sources_[k]);
    if (pressure && ops_.PanelCount(n) > 0) history_transport_ += ops_.TransportMemory(n, k).dot(sources_[k]);
  }
}

StripMarcher::Pending StripMarcher::Compute(const Eigen::VectorXd& v) const {
  const int n = Step();
  if (n >= ops_.Steps())
    throw std::out_of_range("strip marcher: all " + std::to_string(ops_.Steps()) + " steps already taken");
  if (v.size() != ops_.PanelCount(n))
    throw std::invalid_argument("strip marcher: step " + std::to_string(n) + " needs " +
                                std::to_string(ops_.PanelCount(n)) + " normal velocities, got " +
                                std::to_string(v.size()));
  Pending p;
  p.sigma = ops_.Solve(n, v + history_rhs_);
  p.momentum = history_momentum_ + (p.sigma.size() ? ops_.MomentumCurrent(n).dot(p.sigma) : 0.0);
  auto at = [&](int k) { return k >= 0 ? momentum_[k] : 0.0; };
  const auto c = ops_.ForceStencil(n);
  p.force = (c[0] * p.momentum + c[1] * at(n - 1) + c[2] * at(n - 2)) / (2.0 * ops_.Dt());
  if (ops_.Force() == SectionalForce::kPressure && v.size() > 0)  // minus the moving contour's transport term
    p.force -= history_transport_ + ops_.TransportCurrent(n).dot(p.sigma) + ops_.TransportDirect(n).dot(v);
  return p;
}

double StripMarcher::Peek(const Eigen::VectorXd& v) const { return Compute(v).force; }

double StripMarcher::Advance(const Eigen::VectorXd& v) {
  Pending p = Compute(v);
  sources_.push_back(std::move(p.sigma));
  momentum_.push_back(p.momentum);
  PrepareHistory();
  return p.force;
}

}  // namespace hullopt::sk
