#include "optimizer/constraint_set.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hullopt::opt {

ConstraintSet::ConstraintSet(const CampaignDefinition& campaign,
                             const std::vector<std::string>& quantity_names) {
  const auto vars = campaign.VariableNames();
  for (const auto& c : campaign.constraints) {
    Bound b;
    b.is_max = c.kind == Constraint::Kind::kMax;
    b.limit = c.limit;
    b.scale = std::max(std::fabs(c.limit), 1.0);
    auto v = std::find(vars.begin(), vars.end(), c.quantity);
    auto q = std::find(quantity_names.begin(), quantity_names.end(), c.quantity);
    if (v != vars.end()) {
      b.variable = static_cast<int>(v - vars.begin());
    } else if (q != quantity_names.end()) {
      b.quantity = static_cast<int>(q - quantity_names.begin());
      if (std::find(reported_.begin(), reported_.end(), c.quantity) == reported_.end()) {
        reported_.push_back(c.quantity);
        reported_index_.push_back(b.quantity);
      }
    } else {
      throw std::invalid_argument("constraint '" + c.key + "': unknown quantity '" + c.quantity + "'");
    }
    bound_.push_back(b);
  }
}

std::vector<double> ConstraintSet::Values(const std::vector<double>& x, const EvalResult& r) const {
  std::vector<double> g(bound_.size(), 1.0);
  for (std::size_t j = 0; j < bound_.size(); ++j) {
    const Bound& b = bound_[j];
    if (b.variable < 0 && !r.produced) continue;  // refused: violated
    const double q = b.variable >= 0 ? x[b.variable] : r.quantities[b.quantity];
    g[j] = (b.is_max ? q - b.limit : b.limit - q) / b.scale;
  }
  return g;
}

double ConstraintSet::Violation(const std::vector<double>& x, const EvalResult& r) const {
  double v = 0.0;
  for (double g : Values(x, r)) v += std::max(0.0, g);
  return v;
}

bool ConstraintSet::Feasible(const std::vector<double>& x, const EvalResult& r, double tol) const {
  if (!r.produced) return false;
  for (double g : Values(x, r))
    if (g > tol) return false;
  return true;
}

std::vector<double> ConstraintSet::ReportedValues(const EvalResult& r) const {
  std::vector<double> out;
  for (int i : reported_index_) out.push_back(r.produced ? r.quantities[i] : std::nan(""));
  return out;
}

std::vector<double> ConstraintSet::QuantitiesFromReported(const std::vector<double>& reported,
                                                          std::size_t n) const {
  std::vector<double> q(n, std::nan(""));
  for (std::size_t i = 0; i < reported_index_.size() && i < reported.size(); ++i)
    q[reported_index_[i]] = reported[i];
  return q;
}

}  // namespace hullopt::opt
