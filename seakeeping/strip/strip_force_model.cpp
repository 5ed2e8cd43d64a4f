#include "seakeeping/strip/strip_force_model.h"

#include <stdexcept>

namespace hullopt::sk {

KernelStripForceModel::KernelStripForceModel(const StripKernel& kernel) : kernel_(&kernel) { Reset(); }

void KernelStripForceModel::Reset() {
  const int N = kernel_->Steps();
  history_.assign(N, std::vector<Eigen::VectorXd>(N));
  for (auto& slot : history_)
    for (int m = 0; m < N; ++m) slot[m] = Eigen::VectorXd::Zero(kernel_->panels[m].size());
  steps_done_ = 0;
  memory_force_.assign(N, 0.0);
}

void KernelStripForceModel::Store(const std::vector<Eigen::VectorXd>& normal_velocity) {
  const int N = kernel_->Steps();
  if (static_cast<int>(normal_velocity.size()) != N)
    throw std::invalid_argument("KernelStripForceModel: one velocity vector per step expected");
  auto& slot = history_[(steps_done_ - 1) % N];
  for (int m = 0; m < N; ++m) {
    if (normal_velocity[m].size() != slot[m].size())
      throw std::invalid_argument("KernelStripForceModel: velocity vector size differs from the panel count");
    slot[m] = normal_velocity[m];
  }
}

void KernelStripForceModel::Advance(const std::vector<Eigen::VectorXd>& normal_velocity,
                                    std::vector<double>* force_n) {
  const int N = kernel_->Steps();
  const long now = steps_done_++;
  // The memory part: earlier steps of each strip, at the time indices when that strip held them.
  for (int n = 0; n < N; ++n) {
    double f = 0.0;
    for (int m = 0; m < n; ++m) {
      const long when = now - (n - m);
      if (when < 0) continue;  // before the start: calm water, zero velocity
      f += kernel_->force[n][m].dot(history_[when % N][m]);
    }
    memory_force_[n] = f;
  }
  Revise(normal_velocity, force_n);
}

void KernelStripForceModel::Revise(const std::vector<Eigen::VectorXd>& normal_velocity,
                                   std::vector<double>* force_n) {
  if (steps_done_ == 0) throw std::logic_error("KernelStripForceModel::Revise before the first Advance");
  Store(normal_velocity);
  const int N = kernel_->Steps();
  force_n->resize(N);
  for (int n = 0; n < N; ++n) (*force_n)[n] = memory_force_[n] + kernel_->force[n][n].dot(normal_velocity[n]);
}

}  // namespace hullopt::sk
