#include "optimizer/campaign.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "optimizer/nlopt_algorithms.h"

namespace hullopt::opt {
namespace {
std::string Num(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}
bool Contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}
std::string Join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : ", ") + s;
  return out;
}
bool Fail(std::string* error, const std::string& msg) {
  if (error) *error = msg;
  return false;
}
}  // namespace

bool ParseConstraintKey(const std::string& key, std::string* quantity, Constraint::Kind* kind) {
  // Split on '_' and find the last token "max" or "min"; the quantity is the key without that token.
  std::vector<std::string> tokens;
  std::string cur;
  for (char c : key) {
    if (c == '_') {
      tokens.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  tokens.push_back(cur);
  for (int i = static_cast<int>(tokens.size()) - 1; i >= 1; --i) {
    if (tokens[i] != "max" && tokens[i] != "min") continue;
    std::string q;
    for (int j = 0; j < static_cast<int>(tokens.size()); ++j) {
      if (j == i) continue;
      q += (q.empty() ? "" : "_") + tokens[j];
    }
    if (q.empty()) return false;
    *quantity = q;
    *kind = tokens[i] == "max" ? Constraint::Kind::kMax : Constraint::Kind::kMin;
    return true;
  }
  return false;
}

std::vector<double> CampaignDefinition::StartPoint() const {
  std::vector<double> x;
  for (const auto& v : variables) x.push_back(v.start);
  return x;
}
std::vector<double> CampaignDefinition::LowerBounds() const {
  std::vector<double> x;
  for (const auto& v : variables) x.push_back(v.lower);
  return x;
}
std::vector<double> CampaignDefinition::UpperBounds() const {
  std::vector<double> x;
  for (const auto& v : variables) x.push_back(v.upper);
  return x;
}
std::vector<std::string> CampaignDefinition::VariableNames() const {
  std::vector<std::string> x;
  for (const auto& v : variables) x.push_back(v.name);
  return x;
}

bool CampaignDefinition::IsValid(std::string* error) const {
  if (variables.empty()) return Fail(error, "variables: at least one free design variable is needed");
  std::vector<std::string> seen;
  for (const auto& v : variables) {
    if (Contains(seen, v.name)) return Fail(error, "variables: '" + v.name + "' is listed twice");
    seen.push_back(v.name);
    if (!known_variables.empty() && !Contains(known_variables, v.name)) {
      return Fail(error, "variables: unknown design variable '" + v.name +
                             "' (known: " + Join(known_variables) + ")");
    }
    if (!std::isfinite(v.lower) || !std::isfinite(v.upper)) {
      return Fail(error, "variables." + v.name + ": bounds must be finite numbers");
    }
    if (v.lower > v.upper) {
      return Fail(error, "variables." + v.name + ": bounds [" + Num(v.lower) + ", " + Num(v.upper) +
                             "] are inverted (lower must be below upper)");
    }
    if (v.lower == v.upper) {
      return Fail(error, "variables." + v.name + ": bounds [" + Num(v.lower) + ", " + Num(v.upper) +
                             "] are empty (lower == upper); fix the value in the base design instead");
    }
    if (!std::isfinite(v.start) || v.start < v.lower || v.start > v.upper) {
      return Fail(error, "variables." + v.name + ": start value " + Num(v.start) +
                             " is outside the bounds [" + Num(v.lower) + ", " + Num(v.upper) + "]");
    }
  }
  if (!IsNloptAlgorithm(algorithm)) {
    return Fail(error, "algorithm '" + algorithm +
                           "' is not an NLopt algorithm (usable: " + Join(CampaignAlgorithmNames()) + ")");
  }
  if (NeedsGradient(algorithm)) {
    return Fail(error, "algorithm '" + algorithm +
                           "' needs gradients, which the objective does not provide; use a derivative-free "
                           "algorithm (LN_* or GN_*)");
  }
  if (NeedsSubsidiaryOptimizer(algorithm)) {
    return Fail(error,
                "algorithm '" + algorithm +
                    "' needs a subsidiary local optimiser, which campaigns do not configure; use one of: " +
                    Join(CampaignAlgorithmNames()));
  }
  if (stopping.max_evaluations < 1) {
    return Fail(error, "max_evaluations = " + std::to_string(stopping.max_evaluations) + ": must be >= 1");
  }
  if (!std::isfinite(stopping.xtol_rel) || !std::isfinite(stopping.ftol_rel)) {
    return Fail(error, "xtol_rel/ftol_rel must be finite numbers");
  }
  if (!polish_algorithm.empty()) {
    if (!IsNloptAlgorithm(polish_algorithm) || NeedsGradient(polish_algorithm) ||
        NeedsSubsidiaryOptimizer(polish_algorithm) || IsGlobal(polish_algorithm)) {
      return Fail(error, "polish.algorithm '" + polish_algorithm +
                             "' must be a derivative-free local NLopt algorithm (LN_*, e.g. LN_COBYLA)");
    }
    if (polish_max_evaluations < 1) {
      return Fail(error, "polish.max_evaluations = " + std::to_string(polish_max_evaluations) + ": must be >= 1");
    }
  }
  if (starts < 1) return Fail(error, "starts = " + std::to_string(starts) + ": must be >= 1");
  if (!(penalty_weight > 0.0) || !std::isfinite(penalty_weight)) {
    return Fail(error, "penalty_weight = " + Num(penalty_weight) + ": must be a positive number");
  }
  if (!(feasibility_tol >= 0.0) || !std::isfinite(feasibility_tol)) {
    return Fail(error, "feasibility_tol = " + Num(feasibility_tol) + ": must be >= 0");
  }

  // Constraints: known quantity, no contradiction between a min and a max on the same quantity, and a limit
  // on a design variable must leave part of its range.
  std::map<std::string, double> max_of, min_of;
  std::map<std::string, std::string> max_key, min_key;
  for (const auto& c : constraints) {
    if (!std::isfinite(c.limit))
      return Fail(error, "constraints." + c.key + ": limit must be a finite number");
    const bool is_variable = Contains(seen, c.quantity);
    if (!is_variable && !known_quantities.empty() && !Contains(known_quantities, c.quantity)) {
      return Fail(error, "constraints." + c.key + ": unknown quantity '" + c.quantity +
                             "' (constrainable: " + Join(known_quantities) + ", or a design variable)");
    }
    auto& table = c.kind == Constraint::Kind::kMax ? max_of : min_of;
    auto& keys = c.kind == Constraint::Kind::kMax ? max_key : min_key;
    if (table.count(c.quantity)) {
      return Fail(error, "constraints." + c.key + ": quantity '" + c.quantity + "' already limited by '" +
                             keys[c.quantity] + "'");
    }
    table[c.quantity] = c.limit;
    keys[c.quantity] = c.key;
    if (is_variable) {
      const auto& v = *std::find_if(variables.begin(), variables.end(),
                                    [&](const DesignVariable& d) { return d.name == c.quantity; });
      if (c.kind == Constraint::Kind::kMax && c.limit < v.lower) {
        return Fail(error, "constraints." + c.key + " = " + Num(c.limit) + " contradicts the bounds of '" +
                               v.name + "' [" + Num(v.lower) + ", " + Num(v.upper) +
                               "]: no value in the range satisfies it");
      }
      if (c.kind == Constraint::Kind::kMin && c.limit > v.upper) {
        return Fail(error, "constraints." + c.key + " = " + Num(c.limit) + " contradicts the bounds of '" +
                               v.name + "' [" + Num(v.lower) + ", " + Num(v.upper) +
                               "]: no value in the range satisfies it");
      }
      const bool start_violates = c.kind == Constraint::Kind::kMax ? v.start > c.limit : v.start < c.limit;
      if (start_violates && !IsGlobal(algorithm)) {
        return Fail(error, "constraints." + c.key + " = " + Num(c.limit) + ": the start value of '" + v.name +
                               "' (" + Num(v.start) +
                               ") violates it; a local algorithm needs a feasible start");
      }
    }
  }
  for (const auto& [q, hi] : max_of) {
    auto it = min_of.find(q);
    if (it != min_of.end() && it->second > hi) {
      return Fail(error, "constraints " + min_key[q] + " = " + Num(it->second) + " and " + max_key[q] +
                             " = " + Num(hi) + " contradict each other (minimum above maximum of '" + q +
                             "')");
    }
  }
  return true;
}

}  // namespace hullopt::opt
