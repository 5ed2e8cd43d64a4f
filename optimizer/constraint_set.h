#pragma once
// Campaign constraints bound to an evaluator's quantity names: normalised constraint values g_j <= 0 for
// NLopt, penalties, feasibility and the quantity values reported in history.csv.
#include <string>
#include <vector>

#include "optimizer/campaign.h"
#include "optimizer/evaluator.h"

namespace hullopt::opt {

class ConstraintSet {
 public:
  /// Binds each constraint to a design variable (by name) or to an entry of quantity_names. Throws
  /// std::invalid_argument for a quantity that is neither (CampaignDefinition::IsValid reports it first).
  ConstraintSet(const CampaignDefinition& campaign, const std::vector<std::string>& quantity_names);

  std::size_t size() const { return bound_.size(); }
  /// Normalised constraint values g_j = (q − limit)/scale (max) or (limit − q)/scale (min), scale =
  /// max(|limit|, 1); g_j <= 0 means satisfied. For a refused design every g_j is +1 (violated).
  std::vector<double> Values(const std::vector<double>& x, const EvalResult& r) const;
  /// Σ max(0, g_j): total normalised violation.
  double Violation(const std::vector<double>& x, const EvalResult& r) const;
  /// Produced and every g_j <= tol.
  bool Feasible(const std::vector<double>& x, const EvalResult& r, double tol) const;
  /// Quantities constrained that are not design variables, deduplicated, in constraint order: the
  /// history.csv constraint columns.
  const std::vector<std::string>& ReportedQuantities() const { return reported_; }
  /// Values of ReportedQuantities() for a produced result.
  std::vector<double> ReportedValues(const EvalResult& r) const;
  /// Inverse of ReportedValues for replay: a quantities vector of size n with the reported values in place
  /// and NaN elsewhere (only constrained quantities are logged, and only they are used by constraints).
  std::vector<double> QuantitiesFromReported(const std::vector<double>& reported, std::size_t n) const;

 private:
  struct Bound {
    int variable = -1;  // index into x, or
    int quantity = -1;  // index into EvalResult::quantities
    bool is_max = true;
    double limit = 0.0;
    double scale = 1.0;
  };
  std::vector<Bound> bound_;
  std::vector<std::string> reported_;
  std::vector<int> reported_index_;
};

}  // namespace hullopt::opt
