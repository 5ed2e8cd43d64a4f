#pragma once
// Runs a campaign's NLopt optimisation against an Evaluator: baseline evaluation, multistart runs,
// constraints through NLopt inequality constraints where the algorithm supports them (COBYLA, ISRES,
// ORIG_DIRECT, AGS), through NLopt's augmented-Lagrangian penalty (AUGLAG around the chosen algorithm) for
// other local algorithms (BOBYQA, SBPLX, NELDERMEAD, ...) and an exact L1 penalty for other global ones,
// generator refusals as penalised infeasible points, and exact replay of logged evaluations (resume). No I/O:
// each evaluation goes to a RecordSink supplied by the caller.
//
// Determinism: for a given campaign (including the seed) the sequence of evaluated points is fixed; replaying
// logged results reproduces it bit for bit, so a resumed campaign continues exactly where it stopped.
#include <string>
#include <vector>

#include "optimizer/campaign.h"
#include "optimizer/constraint_set.h"
#include "optimizer/evaluation_record.h"
#include "optimizer/evaluator.h"

namespace hullopt::opt {

/// Outcome of one multistart run.
struct RunResult {
  int run = 0;
  std::vector<double> start;    ///< start point
  std::vector<double> best_x;   ///< best feasible point of the run (start if none feasible)
  double best_objective = 0.0;  ///< its objective (not penalised); meaningful if found_feasible
  bool found_feasible = false;
  int evaluations = 0;  ///< evaluations of this run (computed + replayed)
  int replayed = 0;     ///< of which replayed from the log
  std::string status;   ///< NLopt's stopping reason ("MAXEVAL_REACHED", "XTOL_REACHED", ...)
  int polish_evaluations = 0;  ///< evaluations of the polish stage (included in `evaluations`)
  std::string polish_status;   ///< its stopping reason; empty without a polish stage
};

class NloptDriver {
 public:
  /// campaign must be valid (IsValid); the evaluator must outlive the driver.
  NloptDriver(const CampaignDefinition& campaign, Evaluator& evaluator);

  /// Start point of multistart run `run`: the base design for run 0, else uniform in the bounds from a
  /// stream seeded by (seed, run).
  std::vector<double> StartPoint(int run) const;

  /// Evaluates the base design (run −1, step 0), replaying it if logged.
  EvaluationRecord EvaluateBaseline(const ReplayLookup& replay, const RecordSink& sink);

  /// Runs multistart run `run` to its stopping criteria, then its polish stage if the campaign has one (from the
  /// run's best feasible point; skipped when none is feasible). Every evaluation (replayed or computed) goes to sink
  /// in order. Throws ReplayMismatch if the log disagrees with the sequence, and rethrows any non-domain
  /// error of the evaluator.
  RunResult Run(int run, const ReplayLookup& replay, const RecordSink& sink);

  const ConstraintSet& constraints() const { return constraints_; }

  /// Objective NLopt sees for a record: f, or f + penalty for constraint violation when `penalise` (an
  /// algorithm with neither native constraints nor AUGLAG); for a refused design worst_seen + penalty_weight.
  double PenalisedObjective(const EvaluationRecord& rec, double worst_seen, bool penalise) const;

 private:
  EvaluationRecord Evaluate(int run, int step, const std::vector<double>& x, const ReplayLookup& replay);

  CampaignDefinition campaign_;
  EvaluationRecord baseline_;  // reused when run 0 asks for the base design again (no second computation)
  bool has_baseline_ = false;
  Evaluator& evaluator_;
  ConstraintSet constraints_;
};

}  // namespace hullopt::opt
