#include "optimizer/evaluator.h"

#include "optimizer/evaluation_cost.h"

#include <cmath>
#include <stdexcept>

namespace hullopt::opt {

namespace {

EvalResult Checked(Evaluator& evaluator, const std::vector<double>& x) {
  EvalResult r;
  try {
    r = evaluator.Evaluate(x);
  } catch (const std::domain_error& e) {
    r = EvalResult{};
    r.produced = false;
    r.error = e.what();
    return r;
  }
  if (!r.produced) {
    if (r.error.empty()) r.error = "design refused by the evaluator";
    r.sea_values.clear();
    r.quantities.clear();
    return r;
  }
  if (!std::isfinite(r.objective)) {
    r.produced = false;
    r.error = "objective is not a finite number";
    r.sea_values.clear();
    r.quantities.clear();
    return r;
  }
  if (r.sea_values.size() != evaluator.SeaNames().size() ||
      r.quantities.size() != evaluator.QuantityNames().size()) {
    throw std::logic_error("Evaluator returned " + std::to_string(r.sea_values.size()) + " sea values and " +
                           std::to_string(r.quantities.size()) + " quantities, but declares " +
                           std::to_string(evaluator.SeaNames().size()) + " and " +
                           std::to_string(evaluator.QuantityNames().size()));
  }
  // A non-finite value must never reach the log (or a constraint): such a design counts as not produced.
  auto refuse_non_finite = [&](const std::vector<double>& v, const std::vector<std::string>& names) {
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (std::isfinite(v[i])) continue;
      r = EvalResult{};
      r.produced = false;
      r.error = names[i] + " is not a finite number";
      return true;
    }
    return false;
  };
  if (refuse_non_finite(r.sea_values, evaluator.SeaNames())) return r;
  if (refuse_non_finite(r.quantities, evaluator.QuantityNames())) return r;
  return r;
}

}  // namespace

EvalResult EvaluateSafely(Evaluator& evaluator, const std::vector<double>& x) {
  (void)TakeThreadCost();  // what an earlier call on this thread left outside an evaluation
  EvalResult r = Checked(evaluator, x);
  r.cost = TakeThreadCost();
  return r;
}

}  // namespace hullopt::opt
