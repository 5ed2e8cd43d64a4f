#include "seakeeping/strip/marching_strip_force_model.h"

#include <stdexcept>

namespace hullopt::sk {

MarchingStripForceModel::MarchingStripForceModel(const StripOperators& ops) : ops_(&ops) { Reset(); }

void MarchingStripForceModel::Reset() {
  const int N = ops_->Steps();
  strips_.clear();
  pending_.clear();
  // The strip at step n has already passed n steps in calm water with the hull at rest: zero velocity.
  for (int n = 0; n < N; ++n) {
    auto s = std::make_unique<StripMarcher>(*ops_);
    for (int k = 0; k < n; ++k) s->Advance(Eigen::VectorXd::Zero(ops_->PanelCount(k)));
    strips_.push_back(std::move(s));
  }
}

void MarchingStripForceModel::Advance(const std::vector<Eigen::VectorXd>& v, std::vector<double>* force_n) {
  const int N = ops_->Steps();
  if (static_cast<int>(v.size()) != N)
    throw std::invalid_argument("MarchingStripForceModel: one velocity vector per step expected");
  if (!pending_.empty()) {
    // Commit the previous time step, then move every strip on: the one past the stern leaves, a fresh one
    // enters at the bow.
    for (int n = 0; n < N; ++n) strips_[n]->Advance(pending_[n]);
    strips_.pop_back();
    strips_.push_front(std::make_unique<StripMarcher>(*ops_));
  }
  Revise(v, force_n);
}

void MarchingStripForceModel::Revise(const std::vector<Eigen::VectorXd>& v, std::vector<double>* force_n) {
  const int N = ops_->Steps();
  pending_ = v;
  force_n->resize(N);
  for (int n = 0; n < N; ++n) (*force_n)[n] = strips_[n]->Peek(v[n]);
}

}  // namespace hullopt::sk
