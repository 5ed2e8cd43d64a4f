#pragma once
// Analytic test objectives with known optima, used to test and demonstrate the campaign machinery (NLopt
// driver, sampling, resume, parallel runs) without the ship physics. Selected in a campaign config with
// `objective: { analytic: <name> }` (a test/demo feature; real campaigns use the MSI objective).
//
//   sphere      f = Σ (x_i − 1)²                      minimum 0 at x_i = 1
//   rosenbrock  f = Σ 100 (x_{i+1} − x_i²)² + (1 − x_i)²  minimum 0 at x_i = 1
//   rastrigin   f = 10 n + Σ x_i² − 10 cos(2π x_i)     global minimum 0 at x_i = 0, many local minima
//   linear      f = Σ (i+1) x_i                        exact SRC_i = (i+1) σ_i / σ_f (sensitivity tests)
//
// Variables are named x1..x16 or single letters a..z (any order).
// Quantities for constraints: "sum" = Σ x_i and "radius_sq" = Σ x_i². Sea columns: none.
// A design with Σ x_i > refuse_above_sum is refused with std::domain_error, like a generator refusal; one
// with Σ x_i > warn_above_sum is evaluated but carries a warning, like a near-singular hull.
#include <string>
#include <vector>

#include "optimizer/evaluator.h"

namespace hullopt::opt {

struct AnalyticObjectiveOptions {
  std::string function = "sphere";  ///< sphere | rosenbrock | rastrigin | linear
  int dimension = 2;                ///< number of design variables (>= 1; rosenbrock >= 2)
  double eval_delay_ms = 0.0;       ///< [ms] sleep per evaluation, to imitate a slow objective (tests)
  double refuse_above_sum = 1e300;  ///< designs with Σ x_i above this are refused (tests refusal handling)
  double warn_above_sum = 1e300;    ///< designs with Σ x_i above this carry a warning (tests warning handling)
  bool IsValid(std::string* error) const;
};

/// Names of the analytic functions.
std::vector<std::string> AnalyticFunctionNames();

class AnalyticEvaluator : public Evaluator {
 public:
  explicit AnalyticEvaluator(const AnalyticObjectiveOptions& options);
  EvalResult Evaluate(const std::vector<double>& x) override;
  std::vector<std::string> SeaNames() const override { return {}; }
  std::vector<std::string> QuantityNames() const override { return {"sum", "radius_sq"}; }
  /// Any name works for the functions; the test objectives still refuse names outside x1..x16 and a..z, so
  /// that the "unknown variable" check of campaigns can be exercised without the hull generator.
  std::vector<std::string> VariableNames() const override;
  std::string ObjectiveLabel() const override { return options_.function + " (analytic test objective) [-]"; }
  /// The function at x (no delay, no refusal).
  double ObjectiveImplied(const std::vector<double>& x, const std::vector<double>& sea_values) const override;

 private:
  AnalyticObjectiveOptions options_;
};

/// The analytic function values alone (no delay, no refusal).
double AnalyticFunction(const std::string& function, const std::vector<double>& x);

}  // namespace hullopt::opt
