#include "evaluation/trial_design.h"

#include <limits>
#include <sstream>
#include <stdexcept>

#include "evaluation/design_spec.h"
#include "evaluation/hull_plausibility.h"
#include "evaluation/input_error.h"
#include "optimizer/evaluation_cost.h"
#include "parametric_hull/plausibility.h"

namespace hullopt::eval {
namespace {

// A trial value as a config holding it reads back (shortest round-trip digits).
std::string ValueText(double v) {
  std::ostringstream s;
  s.precision(std::numeric_limits<double>::max_digits10);
  s << v;
  return s.str();
}

bool IsTrialField(const std::vector<const hull::DesignVariableField*>& fields, const std::string& name) {
  for (const auto* f : fields)
    if (f && name == f->name) return true;
  return false;
}

}  // namespace

DesignSpec BasisSpec(const DesignBasis& b, const std::string& name) {
  DesignSpec s;
  s.name = name;
  s.source = b.config_file;
  s.water = b.water;
  s.hull.variables = b.variables;
  s.hull.attitude = b.attitude;
  s.speed = b.speed;
  s.solver = b.solver;
  s.has_frequencies = b.has_frequencies;
  return s;
}

std::vector<const hull::DesignVariableField*> TrialFields(const std::vector<std::string>& names) {
  std::vector<const hull::DesignVariableField*> fields;
  for (const auto& n : names) {
    const hull::DesignVariableField* f = hull::FindDesignVariable(n);
    fields.push_back(f && f->campaign_variable ? f : nullptr);
  }
  return fields;
}

DesignCase BuildTrialDesign(const DesignBasis& b, const std::vector<const hull::DesignVariableField*>& fields,
                            const std::vector<double>& x, const std::string& name) {
  const opt::CostTimer timer(opt::CostStage::kAttitude);  // all but the hull generation, timed inside
  const std::string& file = b.config_file;
  hull::DesignVariables v = b.variables;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (!fields[i]) throw InputError(file + ": campaign variable " + std::to_string(i + 1) + " is not a design variable");
    v.*(fields[i]->field) = x.at(i);
  }
  if (const auto bad = v.FirstInvalid()) {
    // As the config reader words it: at the key when the rule is one variable's, else at Cb.
    if (IsTrialField(fields, bad->field))
      throw InputError(file + ":?: key 'hull.parametric." + bad->field + "' = " + ValueText(bad->value) + ": " +
                       bad->rule);
    throw InputError(file + ":?: key 'hull.parametric.Cb': " + bad->Message());
  }
  DesignCase d;
  d.name = name;
  d.water = b.water;
  d.solver = b.solver;
  d.has_frequencies = b.has_frequencies;
  {
    const opt::CostTimer hull_timer(opt::CostStage::kHullGeneration);
    d.hull = GenerateParametricHull(v, file, &d.input_warnings);
  }
  try {
    d.hydrostatics = hull::ComputeHydrostatics(d.hull, d.water.rho_kg_m3);
  } catch (const std::exception& e) {
    throw InputError(file + ": design '" + name + "': " + e.what());
  }
  // The mass a config without `mass:` gets, checked by the same rules, then the campaign's mass rule.
  const hull::Hydrostatics& hs = d.hydrostatics;
  hull::MassProperties defaults;
  defaults.mass_kg = hs.displacement_kg;
  defaults.lcg_m_from_ap = hs.lcb_m_from_ap;
  defaults.kyy_m = kDefaultKyyOverL * hs.L_m;
  defaults.kg_m = kDefaultKgOverT * hs.T_m;
  for (const auto& f : hull::CheckMassPlausibility(defaults, hs, false)) {
    if (f.refuse) throw InputError(file + ":?: key 'mass." + f.quantity + "': " + f.message);
    d.input_warnings.push_back(f.message);
  }
  d.speed_m_s = b.speed.MetresPerSecond(hs.L_m, d.water.g_m_s2);
  d.mass.mass_kg = hs.displacement_kg;
  d.mass.lcg_m_from_ap = hs.lcb_m_from_ap;
  d.mass.kyy_m = b.kyy_over_L * hs.L_m;
  d.mass.kg_m = b.kg_over_T * hs.T_m;
  d.hydrostatics = hull::ComputeHydrostatics(d.hull, d.water.rho_kg_m3, d.mass.kg_m);
  // The attitude and the validity envelope as for a design read from a config: a trial beyond a hard limit is
  // not produced (its error is its message), one within is flagged in its row.
  FinishDesign(&d, b.attitude, file, file + ": design '" + name + "'", /*has_speed=*/true);
  return d;
}

}  // namespace hullopt::eval
