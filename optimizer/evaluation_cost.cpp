#include "optimizer/evaluation_cost.h"

namespace hullopt::opt {
namespace {

thread_local EvalCost t_cost;
thread_local CostTimer* t_innermost = nullptr;

}  // namespace

const char* CostStageName(CostStage stage) {
  switch (stage) {
    case CostStage::kHullGeneration:
      return "hull_generation";
    case CostStage::kAttitude:
      return "hydrostatics_attitude";
    case CostStage::kPanelling:
      return "panelling";
    case CostStage::kKernelBuild:
      return "kernel_build";
    case CostStage::kPeriodicSolve:
      return "periodic_solve";
    case CostStage::kObliqueSolve:
      return "oblique_solve";
    case CostStage::kSeas:
      return "spectra_msi";
    case CostStage::kResistance:
      return "resistance";
    case CostStage::kCount:
      break;
  }
  return "?";
}

double EvalCost::Sum() const {
  double s = 0.0;
  for (double v : seconds) s += v;
  return s;
}

CostTimer::CostTimer(CostStage stage)
    : stage_(stage), parent_(t_innermost), t0_(std::chrono::steady_clock::now()) {
  t_innermost = this;
}

CostTimer::~CostTimer() {
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  t_cost[stage_] += s - nested_s_;
  if (parent_) parent_->nested_s_ += s;
  t_innermost = parent_;
}

EvalCost TakeThreadCost() {
  EvalCost c = t_cost;
  c.measured = true;
  t_cost = EvalCost{};
  return c;
}

}  // namespace hullopt::opt
