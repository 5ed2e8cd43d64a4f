#include "evaluation/design_spec.h"

#include <atomic>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "evaluation/hull_plausibility.h"
#include "evaluation/input_error.h"
#include "evaluation/strip_attitude.h"
#include "evaluation/trial_design.h"
#include "evaluation/validity_envelope.h"
#include "parametric_hull/hull_generator.h"
#include "parametric_hull/plausibility.h"

namespace hullopt::eval {
namespace {

std::atomic<long> g_hulls{0};

std::string KeyWhere(const MassSpec& m, const std::string& source, const std::string& key) {
  const auto it = m.where.find(key);
  return it != m.where.end() ? it->second : source + ": key 'mass." + key + "'";
}

}  // namespace

DesignBuildCounts BuildCounts() { return {g_hulls.load(), CalmWaterSolves()}; }

bool MassSpec::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (mass_kg && !(*mass_kg > 0.0)) return fail("mass.mass_kg must be > 0");
  if (kyy_over_L && kyy_m) return fail("mass.kyy_over_L: give kyy_m or kyy_over_L, not both");
  if (kg_over_T && kg_m) return fail("mass.kg_over_T: give kg_m or kg_over_T, not both");
  if (kyy_over_L && !(*kyy_over_L > 0.05 && *kyy_over_L < 0.5))
    return fail("mass.kyy_over_L must be within 0.05..0.5");
  if (kyy_m && !(*kyy_m > 0.0)) return fail("mass.kyy_m must be > 0 (typically 0.25 L)");
  if (kg_over_T && !(*kg_over_T > 0 && *kg_over_T < 10)) return fail("mass.kg_over_T must be within 0..10");
  return true;
}

hull::MassProperties ResolveMass(const MassSpec& m, const hull::Hydrostatics& hs, const std::string& source,
                                 std::vector<std::string>* warnings) {
  if (std::string e; !m.IsValid(&e)) throw InputError(source + ": " + e);
  hull::MassProperties p;
  p.mass_kg = m.mass_kg.value_or(hs.displacement_kg);
  p.lcg_m_from_ap = m.lcg_m_from_ap.value_or(hs.lcb_m_from_ap);
  const double x0 = hs.x_ap_m, x1 = hs.x_ap_m + hs.L_m;
  if (p.lcg_m_from_ap < x0 || p.lcg_m_from_ap > x1) {
    std::ostringstream os;
    os << "must lie on the waterline length, between " << x0 << " and " << x1 << " m from the AP";
    throw InputError(KeyWhere(m, source, "lcg_m_from_ap") + ": " + os.str());
  }
  p.kyy_m = m.kyy_over_L ? *m.kyy_over_L * hs.L_m : m.kyy_m.value_or(kDefaultKyyOverL * hs.L_m);
  p.kg_m = m.kg_over_T ? *m.kg_over_T * hs.T_m : m.kg_m.value_or(kDefaultKgOverT * hs.T_m);
  for (const auto& f : hull::CheckMassPlausibility(p, hs, m.accept_mass_mismatch)) {
    if (f.refuse) throw InputError(KeyWhere(m, source, f.quantity) + ": " + f.message);
    if (warnings) warnings->push_back(f.message);
  }
  return p;
}

hull::HullForm GenerateParametricHull(const hull::DesignVariables& v, const std::string& source,
                                      std::vector<std::string>* warnings) {
  ++g_hulls;
  hull::HullForm h;
  try {
    h = hull::GenerateHull(v);
  } catch (const std::logic_error& e) {  // invalid_argument and domain_error
    throw InputError(source + ": key 'hull.parametric': " + e.what());
  }
  std::vector<std::string> w = CheckHull(h, source + ": key 'hull.parametric'");
  if (warnings) warnings->insert(warnings->end(), w.begin(), w.end());
  return h;
}

hull::HullForm BuildHull(const DesignSpec& spec, std::vector<std::string>* warnings) {
  if (spec.hull.parametric) return GenerateParametricHull(spec.hull.variables, spec.source, warnings);
  if (warnings)
    warnings->insert(warnings->end(), spec.hull.given_warnings.begin(), spec.hull.given_warnings.end());
  return spec.hull.given;
}

void FinishDesign(DesignCase* d, const hull::RunningAttitude& given, const std::string& source,
                  const std::string& envelope_where, bool has_speed) {
  if (has_speed && d->solver.steady_flow) {
    d->attitude = StripAttitude(d->hull, d->mass, d->speed_m_s, d->water, d->solver, given,
                                source + ": design '" + d->name + "'");
    d->running_hull = hull::ApplyRunningAttitude(d->hull, d->attitude);
  } else {
    d->attitude = given;
    d->attitude.pivot_x_m = d->mass.lcg_m_from_ap;
    try {
      d->running_hull = hull::ApplyRunningAttitude(d->hull, d->attitude);
    } catch (const std::logic_error& e) {  // invalid_argument and domain_error
      throw InputError(source + ": key 'hull.attitude': " + e.what());
    }
  }
  // The method's validity envelope: refused beyond its hard limits, flagged in every output within them.
  for (auto& w : ApplyDesignEnvelope(d->water, has_speed ? d->speed_m_s : NAN, d->solver.cs(), d->hull,
                                     d->hydrostatics, &d->mass, envelope_where))
    d->input_warnings.push_back(std::move(w));
}

DesignCase BuildDesign(const DesignSpec& spec) {
  DesignCase d;
  d.name = spec.name;
  d.water = spec.water;
  d.solver = spec.solver;
  d.has_frequencies = spec.has_frequencies;
  d.hull = BuildHull(spec, &d.input_warnings);
  try {
    d.hydrostatics = hull::ComputeHydrostatics(d.hull, d.water.rho_kg_m3);
  } catch (const std::exception& e) {
    throw InputError(spec.source + ": design '" + spec.name + "': " + e.what());
  }
  d.mass = ResolveMass(spec.mass, d.hydrostatics, spec.source, &d.input_warnings);
  if (spec.has_speed) d.speed_m_s = spec.speed.MetresPerSecond(d.hydrostatics.L_m, d.water.g_m_s2);
  FinishDesign(&d, spec.hull.attitude, spec.source, spec.source, spec.has_speed);
  return d;
}

}  // namespace hullopt::eval
