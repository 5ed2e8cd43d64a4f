#pragma once
// What a campaign is asked to do, independent of any file format: the free design variables with bounds and
// start values, the constraints on named quantities, the NLopt algorithm and stopping criteria, multistart
// and the random seed. Filled by io/config/campaign_config from YAML; validated here so that every bad input
// is refused before the first evaluation.
#include <cstdint>
#include <string>
#include <vector>

namespace hullopt::opt {

/// One free design variable.
struct DesignVariable {
  std::string name;    ///< generator variable name, e.g. "L_over_B" (units as the generator defines them)
  double lower = 0.0;  ///< lower bound
  double upper = 0.0;  ///< upper bound (> lower)
  double start = 0.0;  ///< base-design value; the first multistart run starts here
};

/// A limit on a named quantity: quantity <= limit (kMax) or quantity >= limit (kMin).
struct Constraint {
  enum class Kind { kMax, kMin };
  std::string key;       ///< as written in the config, e.g. "L_max_m" (for messages and column names)
  std::string quantity;  ///< the quantity it limits, e.g. "L_m"
  Kind kind = Kind::kMax;
  double limit = 0.0;
};

/// Parses a constraint key "<quantity>_max[_unit]" or "<quantity>_min[_unit]" into the quantity name
/// "<quantity>[_unit]" and the kind. "L_max_m" → ("L_m", kMax); "Cvp_min" → ("Cvp", kMin);
/// "GM_T_min_m" → ("GM_T_m", kMin). Returns false if the key has no "_max"/"_min" part.
bool ParseConstraintKey(const std::string& key, std::string* quantity, Constraint::Kind* kind);

/// Stopping criteria of one local/global optimisation run (NLopt semantics). A value <= 0 disables xtol/ftol.
struct StoppingCriteria {
  int max_evaluations = 200;  ///< per run
  double xtol_rel = 1e-6;     ///< relative change of the variables
  double ftol_rel = 1e-8;     ///< relative change of the objective
};

/// A whole optimisation / exploration campaign.
struct CampaignDefinition {
  std::vector<DesignVariable> variables;
  std::vector<Constraint> constraints;
  std::string algorithm = "LN_COBYLA";  ///< NLopt algorithm name
  StoppingCriteria stopping;
  int starts = 1;          ///< multistart runs; run 0 starts at the base design
  /// Optional local polish of every run: a second NLopt run with this local (LN_*) algorithm from the run's
  /// best feasible point, up to polish_max_evaluations more evaluations, logged as steps of the same run.
  /// NLopt's advice for global algorithms, which locate the basin but converge slowly within it. Empty: none.
  std::string polish_algorithm;
  int polish_max_evaluations = 200;
  std::uint64_t seed = 1;  ///< seeds multistart start points, stochastic algorithms and LHS
  /// Penalty weight for the penalty method (algorithms without inequality constraints): the objective of
  /// a point violating constraints becomes f + penalty_weight·Σ max(0, g_j)/scale_j. [objective units]
  double penalty_weight = 1000.0;
  /// Relative tolerance on a constraint for a point to count as feasible: g_j <= feasibility_tol·scale_j,
  /// scale_j = max(|limit_j|, 1). COBYLA converges onto active constraints from either side.
  double feasibility_tol = 1e-6;

  /// Names of the quantities the evaluator provides (for "unknown quantity" errors); empty = skip that check.
  std::vector<std::string> known_quantities;
  /// Names the variables may take (generator variables); empty = any name accepted.
  std::vector<std::string> known_variables;

  /// Checks everything that can be checked without evaluating: variables known, bounds ordered and non-empty,
  /// start inside bounds, algorithm a derivative-free NLopt algorithm, stopping criteria positive,
  /// constraints on known quantities and not contradictory (min > max on one quantity, or a limit on a design
  /// variable that excludes its whole range). The message names the item, the value and the rule.
  bool IsValid(std::string* error) const;

  std::vector<double> StartPoint() const;
  std::vector<double> LowerBounds() const;
  std::vector<double> UpperBounds() const;
  std::vector<std::string> VariableNames() const;
};

}  // namespace hullopt::opt
