#pragma once
// The designs of a campaign: a base parametric design whose free variables a trial sets field by field, then
// the hull, hydrostatics, mass, attitude and speed follow as they would for a config that gave those values.
#include <string>
#include <vector>

#include "evaluation/design_case.h"
#include "evaluation/design_speed.h"
#include "parametric_hull/design_variables.h"
#include "parametric_hull/running_attitude.h"

namespace hullopt::eval {

/// The mass rule of a design without `mass:` (single designs and campaign trials alike): mass = displacement,
/// LCG = LCB, k_yy = kDefaultKyyOverL L (the usual 0.25 L of fast craft), KG = kDefaultKgOverT T (KG does not
/// enter heave and pitch; the draught keeps it plausible).
constexpr double kDefaultKyyOverL = 0.25;
constexpr double kDefaultKgOverT = 1.0;

/// What a campaign holds fixed about its designs.
struct DesignBasis {
  std::string config_file;          ///< names the source in messages
  hull::DesignVariables variables;  ///< the base parametric hull (rho from the water)
  hull::RunningAttitude attitude;   ///< pivot set at each design's centre of gravity
  WaterOptions water;
  SpeedOptions speed;
  SolverSettings solver;
  bool has_frequencies = false;
  /// Mass follows the design: the displacement is fixed, LCG = LCB, k_yy = kyy_over_L L, KG = kg_over_T T.
  double kyy_over_L = kDefaultKyyOverL;
  double kg_over_T = kDefaultKgOverT;
};

/// The base design of a campaign as a single-design spec: its own variables, water, speed and solver, the
/// mass of a config without `mass:` (not the campaign's mass rule), named `name` in messages.
struct DesignSpec;
DesignSpec BasisSpec(const DesignBasis& basis, const std::string& name);

/// The free variables of a campaign, in its order (the fields of x); nullptr for a name that is not a campaign
/// variable of DesignVariableFields() (the campaign's own check names it, opt::CampaignDefinition).
std::vector<const hull::DesignVariableField*> TrialFields(const std::vector<std::string>& names);

/// The design named `name` at x (one value per field, in order). Throws InputError naming the config key and
/// rule for values the rules or the generator refuse, as the config with these values would.
DesignCase BuildTrialDesign(const DesignBasis& basis, const std::vector<const hull::DesignVariableField*>& fields,
                            const std::vector<double>& x, const std::string& name = "design");

}  // namespace hullopt::eval
