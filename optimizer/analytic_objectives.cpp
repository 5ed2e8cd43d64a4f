#include "optimizer/analytic_objectives.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace hullopt::opt {

std::vector<std::string> AnalyticFunctionNames() { return {"sphere", "rosenbrock", "rastrigin", "linear"}; }

bool AnalyticObjectiveOptions::IsValid(std::string* error) const {
  bool known = false;
  for (const auto& f : AnalyticFunctionNames()) known = known || f == function;
  if (!known) {
    if (error) *error = "analytic = " + function + ": must be one of sphere, rosenbrock, rastrigin, linear";
    return false;
  }
  if (dimension < 1 || (function == "rosenbrock" && dimension < 2)) {
    if (error)
      *error = "analytic " + function + ": needs at least " + (function == "rosenbrock" ? "2" : "1") +
               " design variables, got " + std::to_string(dimension);
    return false;
  }
  if (!(eval_delay_ms >= 0.0) || eval_delay_ms > 60000.0) {
    if (error) *error = "eval_delay_ms = " + std::to_string(eval_delay_ms) + ": must be in [0, 60000]";
    return false;
  }
  return true;
}

double AnalyticFunction(const std::string& function, const std::vector<double>& x) {
  constexpr double kPi = 3.14159265358979323846;
  double f = 0.0;
  const std::size_t n = x.size();
  if (function == "sphere") {
    for (double v : x) f += (v - 1.0) * (v - 1.0);
  } else if (function == "rosenbrock") {
    for (std::size_t i = 0; i + 1 < n; ++i) {
      f += 100.0 * (x[i + 1] - x[i] * x[i]) * (x[i + 1] - x[i] * x[i]) + (1.0 - x[i]) * (1.0 - x[i]);
    }
  } else if (function == "rastrigin") {
    f = 10.0 * static_cast<double>(n);
    for (double v : x) f += v * v - 10.0 * std::cos(2.0 * kPi * v);
  } else if (function == "linear") {
    for (std::size_t i = 0; i < n; ++i) f += static_cast<double>(i + 1) * x[i];
  } else {
    throw std::invalid_argument("unknown analytic function '" + function + "'");
  }
  return f;
}

std::vector<std::string> AnalyticEvaluator::VariableNames() const {
  std::vector<std::string> names;
  for (int i = 1; i <= 16; ++i) names.push_back("x" + std::to_string(i));
  for (char c = 'a'; c <= 'z'; ++c) names.push_back(std::string(1, c));
  return names;
}

AnalyticEvaluator::AnalyticEvaluator(const AnalyticObjectiveOptions& options) : options_(options) {
  std::string error;
  if (!options_.IsValid(&error)) throw std::invalid_argument(error);
}

double AnalyticEvaluator::ObjectiveImplied(const std::vector<double>& x, const std::vector<double>&) const {
  return AnalyticFunction(options_.function, x);
}

EvalResult AnalyticEvaluator::Evaluate(const std::vector<double>& x) {
  if (options_.eval_delay_ms > 0.0) {
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(options_.eval_delay_ms));
  }
  double sum = 0.0, r2 = 0.0;
  for (double v : x) {
    sum += v;
    r2 += v * v;
  }
  if (sum > options_.refuse_above_sum) {
    throw std::domain_error("sum of the variables " + std::to_string(sum) + " exceeds refuse_above_sum " +
                            std::to_string(options_.refuse_above_sum));
  }
  EvalResult r;
  r.objective = AnalyticFunction(options_.function, x);
  r.quantities = {sum, r2};
  if (sum > options_.warn_above_sum)
    r.warning = "sum of the variables " + std::to_string(sum) + " exceeds warn_above_sum " +
                std::to_string(options_.warn_above_sum);
  return r;
}

}  // namespace hullopt::opt
