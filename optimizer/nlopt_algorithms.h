#pragma once
// Facts about NLopt algorithms the campaign needs, looked up by NLopt name ("LN_COBYLA", "GN_ISRES", ...).
#include <string>
#include <vector>

namespace hullopt::opt {

/// True if `name` is an algorithm of the installed NLopt (nlopt_algorithm_from_string).
bool IsNloptAlgorithm(const std::string& name);
/// All algorithm names of the installed NLopt, for error messages.
std::vector<std::string> NloptAlgorithmNames();
/// Names usable by a campaign: derivative-free (LN_*, GN_*) and not needing a subsidiary optimiser.
std::vector<std::string> CampaignAlgorithmNames();
/// Derivative-based (LD_*, GD_*): need gradients the MSI objective does not provide.
bool NeedsGradient(const std::string& name);
/// AUGLAG*, G_MLSL*, GN_MLSL*: need a subsidiary local optimiser.
bool NeedsSubsidiaryOptimizer(const std::string& name);
/// Global algorithm (GN_*, GD_*, G_*): needs finite bounds on every variable.
bool IsGlobal(const std::string& name);
/// Supports nonlinear inequality constraints natively (else the campaign uses a penalty).
bool SupportsInequalityConstraints(const std::string& name);
/// Uses random numbers (seeded through nlopt::srand for reproducibility).
bool IsStochastic(const std::string& name);

}  // namespace hullopt::opt
