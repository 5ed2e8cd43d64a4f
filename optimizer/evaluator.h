#pragma once
// The abstract evaluation a campaign optimises or explores: design variables in, objective and named
// quantities out. The campaign machinery (NLopt driver, sampling, resume, parallel runs) only sees this
// interface; the MSI evaluator (hull generator + motions + seas) and the analytic test objectives implement
// it.
#include <limits>
#include <string>
#include <vector>

#include "optimizer/evaluation_cost.h"

namespace hullopt::opt {

/// Result of one evaluation of a design.
struct EvalResult {
  /// Objective to minimise (e.g. mean MSI [%]). Meaningful only if `produced`.
  double objective = 0.0;
  /// One value per Evaluator::SeaNames() entry (e.g. mean MSI [%] in each sea); empty if not produced.
  std::vector<double> sea_values;
  /// One value per Evaluator::QuantityNames() entry (e.g. L_m, B_overall_m, GM_T_m); constraints refer to
  /// these by name. Empty if not produced.
  std::vector<double> quantities;
  /// false when the design could not be built or evaluated (generator refusal: std::domain_error). The
  /// campaign treats such a point as infeasible; it never stops the campaign.
  bool produced = true;
  /// Why the design was refused (the generator's message); empty when produced.
  std::string error;
  /// A produced design's non-fatal note (e.g. near-singular strip sections, whose RAOs may be unconverged);
  /// empty when there is none. history.csv carries it in `message` as "warning: ...".
  std::string warning;
  /// Wall time of the evaluation's stages (EvaluateSafely fills it; not logged, not compared).
  EvalCost cost;
};

/// A design evaluation. Implementations must be deterministic (same x → same result, bit for bit) and, if
/// IsThreadSafe() returns true, safe to call concurrently from several threads (explore runs samples in
/// parallel with OpenMP).
class Evaluator {
 public:
  virtual ~Evaluator() = default;
  /// Evaluates the design with free variables x (ordered as in the campaign definition). May throw
  /// std::domain_error for a design the generator refuses; EvaluateSafely turns that into produced = false.
  virtual EvalResult Evaluate(const std::vector<double>& x) = 0;
  /// Names of the per-sea columns of EvalResult::sea_values (history.csv column names, e.g. "msi_sea1_pct").
  virtual std::vector<std::string> SeaNames() const = 0;
  /// Names of the quantities of EvalResult::quantities that constraints may refer to.
  virtual std::vector<std::string> QuantityNames() const = 0;
  /// Axis label of the objective with its unit, for plots (e.g. "mean MSI [%]").
  virtual std::string ObjectiveLabel() const { return "objective"; }
  /// How the objective is computed when the label alone does not say it (e.g. which motion method over which
  /// headings), one sentence for summary.json's `objective_method`; empty: nothing to add.
  virtual std::string ObjectiveMethod() const { return ""; }
  /// Names the free design variables may take (e.g. the generator's variables); empty = any name.
  virtual std::vector<std::string> VariableNames() const { return {}; }
  virtual bool IsThreadSafe() const { return true; }
  /// The objective a produced result of design x must have, computed from x and the result's per-sea values
  /// without the expensive part of an evaluation (the MSI objective is the weighted mean of the per-sea
  /// values; an analytic objective is its formula); NaN when it cannot be computed that way. Used to check
  /// every row of a campaign log on resume.
  virtual double ObjectiveImplied(const std::vector<double>& x, const std::vector<double>& sea_values) const {
    (void)x;
    (void)sea_values;
    return std::numeric_limits<double>::quiet_NaN();
  }
};

/// Calls evaluator.Evaluate(x) and converts a std::domain_error (generator refusal) into an EvalResult with
/// produced = false and the message in `error`. Also marks a non-finite objective as not produced, so that
/// no NaN is ever used as an objective value. Checks the result's vector sizes against the evaluator's names.
EvalResult EvaluateSafely(Evaluator& evaluator, const std::vector<double>& x);

}  // namespace hullopt::opt
