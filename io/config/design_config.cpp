#include "io/config/design_config.h"

#include "evaluation/hull_plausibility.h"
#include "evaluation/strip_attitude.h"
#include "io/formats/input_error.h"
#include "io/config/motion_config.h"
#include "io/config/water_config.h"

namespace hullopt::io {

std::string ParseDesignName(YamlMap& root, const std::string& fallback) {
  const std::string name = root.String("name", fallback);
  if (name.empty()) root.Fail("name", "must not be empty");
  return name;
}

eval::DesignCase LoadDesignCase(YamlMap& root, const std::string& config_file, const std::string& name,
                                bool read_speed, DesignConfig* config) {
  eval::DesignCase d;
  d.name = name;
  d.water = ParseWater(root);
  const HullOptions hull_opts = ParseHullConfig(root, d.water);
  const SpeedOptions speed = read_speed ? ParseSpeed(root, true) : SpeedOptions{};
  d.hull = LoadHull(hull_opts, config_file, &d.input_warnings);
  if (root.Has("solver")) {
    YamlMap s = root.Map("solver");
    d.has_frequencies = s.Has("frequencies");
    if (s.Has("kernel")) s.Choice("kernel", {"transient_green"}, "transient_green");
    // Evaluations in seas choose their own frequency grid, so solver.frequencies is optional here.
    d.solver = ParseSolverConfig(s, /*frequencies_required=*/false);
  }
  try {
    d.hydrostatics = hull::ComputeHydrostatics(d.hull, d.water.rho_kg_m3);
  } catch (const std::exception& e) {
    throw InputError(config_file + ": design '" + name + "': " + e.what());
  }
  YamlMap mass_map = root.MapOrEmpty("mass");
  d.mass = ParseMassConfig(mass_map, d.hydrostatics, &d.input_warnings);
  if (read_speed) d.speed_m_s = speed.MetresPerSecond(d.hydrostatics.L_m, d.water.g_m_s2);
  if (read_speed && d.solver.steady_flow) {
    d.attitude = eval::StripAttitude(d.hull, d.mass, d.speed_m_s, d.water, d.solver, hull_opts.attitude,
                                     config_file + ": design '" + name + "'");
    d.running_hull = hull::ApplyRunningAttitude(d.hull, d.attitude);
  } else {
    d.attitude = hull_opts.attitude;
    d.attitude.pivot_x_m = d.mass.lcg_m_from_ap;
    d.running_hull = ApplyHullAttitude(hull_opts, d.hull, d.mass.lcg_m_from_ap, config_file);
  }
  // The method's validity envelope: refused beyond its hard limits, flagged in every output within them.
  eval::EnvelopeInput env;
  env.rho_kg_m3 = d.water.rho_kg_m3;
  env.g_m_s2 = d.water.g_m_s2;
  if (read_speed) env.speed_m_s = d.speed_m_s;
  env.cs = d.solver.cs();
  env.hull = &d.hull;
  env.hs = &d.hydrostatics;
  env.mass = &d.mass;
  for (auto& w : eval::ApplyEnvelope(eval::CheckEnvelope(env), config_file)) d.input_warnings.push_back(std::move(w));
  if (config) *config = {d.water, hull_opts, speed, d.solver, d.has_frequencies};
  return d;
}

eval::DesignBasis TrialBasis(const DesignConfig& c, const std::string& config_file) {
  eval::DesignBasis b;
  b.config_file = config_file;
  b.variables = c.hull.design;
  b.attitude = c.hull.attitude;
  b.water = c.water;
  b.speed = c.speed;
  b.solver = c.solver;
  b.has_frequencies = c.has_frequencies;
  return b;
}

}  // namespace hullopt::io
