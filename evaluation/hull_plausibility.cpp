#include "evaluation/hull_plausibility.h"

#include <stdexcept>

#include "evaluation/input_error.h"
#include "parametric_hull/hydrostatics.h"

namespace hullopt::eval {

std::vector<std::string> ApplyFindings(const std::vector<hull::PlausibilityFinding>& findings,
                                       const std::string& where) {
  std::vector<std::string> warnings;
  for (const auto& f : findings)
    if (f.refuse) throw InputError(where + ": " + f.message);
  for (const auto& f : findings) warnings.push_back(f.message);
  return warnings;
}

std::vector<std::string> CheckHull(const hull::HullForm& hull, const std::string& where) {
  hull::Hydrostatics hs;
  try {
    hs = hull::ComputeHydrostatics(hull);
  } catch (const std::logic_error& e) {
    throw InputError(where + ": " + e.what());
  }
  return ApplyFindings(hull::CheckHullPlausibility(hull, hs), where);
}

std::vector<std::string> ApplyEnvelope(const std::vector<EnvelopeFinding>& findings, const std::string& where) {
  std::vector<std::string> warnings;
  for (const auto& f : findings)
    if (f.refuse) throw InputError(where + ": key '" + f.key + "': " + f.message);
  for (const auto& f : findings) warnings.push_back(f.message);
  return warnings;
}

std::vector<std::string> ApplyDesignEnvelope(const WaterOptions& water, double speed_m_s, double cs,
                                             const hull::HullForm& hull, const hull::Hydrostatics& hs,
                                             const hull::MassProperties* mass, const std::string& where) {
  EnvelopeInput env;
  env.rho_kg_m3 = water.rho_kg_m3;
  env.g_m_s2 = water.g_m_s2;
  env.speed_m_s = speed_m_s;
  env.cs = cs;
  env.hull = &hull;
  env.hs = &hs;
  env.mass = mass;
  return ApplyEnvelope(CheckEnvelope(env), where);
}

}  // namespace hullopt::eval
