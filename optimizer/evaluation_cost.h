#pragma once
// Where the time of a design evaluation goes (the campaigns' --profile): the evaluation layer wraps each stage of
// its chain (hull generation, attitude, panelling, kernel build, periodic solve, seas, resistance) in a CostTimer;
// the times add up per thread, and EvaluateSafely hands the evaluation's split over in EvalResult::cost. Timers
// nest: a stage timed inside another (the kernel build inside the solver's set-up) counts for itself only, and
// the enclosing stage keeps the rest. Nothing here prints; the physics is not timed inside, only around.
#include <array>
#include <chrono>

namespace hullopt::opt {

enum class CostStage : int {
  kHullGeneration,  ///< the parametric hull from the design variables
  kAttitude,        ///< hydrostatics at rest, the mass rule, the calm-water running attitude, the envelope
  kPanelling,       ///< the strips' sections cut and panelled (the solver's set-up without the kernel)
  kKernelBuild,     ///< the strip kernel's force rows (transient Green function)
  kPeriodicSolve,   ///< the RAOs at the frequencies (periodic solve; strip theory's sections)
  kObliqueSolve,    ///< the oblique-sea strip theory over headings (sections and solve)
  kSeas,            ///< spectra, responses and MSI (with the adaptive grid's passes)
  kResistance,      ///< calm-water resistance at the design speed
  kCount
};

/// Short name of a stage (summary.json key, --profile line).
const char* CostStageName(CostStage stage);

/// Seconds of wall time per stage of one evaluation (or summed over several).
struct EvalCost {
  std::array<double, static_cast<int>(CostStage::kCount)> seconds{};
  bool measured = false;  ///< true for an evaluation computed here (not replayed, not received from another rank)
  double& operator[](CostStage s) { return seconds[static_cast<int>(s)]; }
  double operator[](CostStage s) const { return seconds[static_cast<int>(s)]; }
  double Sum() const;
};

/// Adds the wall time of its scope, less that of timers nested in it, to `stage` of this thread's evaluation.
class CostTimer {
 public:
  explicit CostTimer(CostStage stage);
  ~CostTimer();
  CostTimer(const CostTimer&) = delete;
  CostTimer& operator=(const CostTimer&) = delete;

 private:
  CostStage stage_;
  CostTimer* parent_;
  double nested_s_ = 0.0;
  std::chrono::steady_clock::time_point t0_;
};

/// This thread's times since the last call (marked measured), and resets them.
EvalCost TakeThreadCost();

}  // namespace hullopt::opt
