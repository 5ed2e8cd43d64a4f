#pragma once
// One evaluation of a campaign as it is logged (history.csv / samples.csv row) and replayed on resume.
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "optimizer/evaluator.h"

namespace hullopt::opt {

struct EvaluationRecord {
  int run = 0;            ///< multistart run (0-based); for exploration always 0
  int step = 0;           ///< position in its run's deterministic sequence (0-based)
  std::vector<double> x;  ///< free design variables, in campaign order
  EvalResult result;
  bool feasible = false;   ///< produced and every constraint satisfied
  double wall_time_s = 0;  ///< [s] wall time of the evaluation when it was computed
  bool replayed = false;   ///< taken from an earlier run's log instead of computed now
};

/// Looks up an evaluation computed by an earlier, interrupted run: (run, step) → record, or nullptr if it
/// was not computed yet. Used to resume a campaign without recomputing anything.
using ReplayLookup = std::function<const EvaluationRecord*(int run, int step)>;
/// Receives each evaluation as soon as it is known (computed or replayed), in sequence order.
using RecordSink = std::function<void(const EvaluationRecord&)>;

/// The logged inputs of evaluation (run, step) differ from what the deterministic sequence asks for now:
/// the log belongs to a different campaign and cannot be resumed.
class ReplayMismatch : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Returns the logged record for (run, step) after checking that its inputs equal x bit for bit; nullptr if
/// there is none. Throws ReplayMismatch when they differ.
const EvaluationRecord* LookupReplay(const ReplayLookup& lookup, int run, int step,
                                     const std::vector<double>& x);

}  // namespace hullopt::opt
