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
  earlier_momentum_ = {0.0, 0.0};
  const bool pressure = ops_.Force() == SectionalForce::kPressure;
  for (int k = 0; k < n; ++k) {
    if (sources_[k].size() == 0) continue;
    if (history_rhs_.size() > 0) history_rhs_ += ops_.Memory(n, k) * sources_[k];
    history_momentum_ += ops_.MomentumMemory(n, k).dot(sources_[k]);
    for (int s = 1; pressure && s <= 2; ++s)
      if (k <= n - s) earlier_momentum_[s - 1] += ops_.PressureMomentum(s, n, k).dot(sources_[k]);
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
  if (ops_.Force() == SectionalForce::kPressure)  // momenta of earlier potentials on this contour
    p.force = (c[0] * p.momentum + c[1] * earlier_momentum_[0] + c[2] * earlier_momentum_[1]) / (2.0 * ops_.Dt());
  else
    p.force = (c[0] * p.momentum + c[1] * at(n - 1) + c[2] * at(n - 2)) / (2.0 * ops_.Dt());
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
