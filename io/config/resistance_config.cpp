#include "io/config/resistance_config.h"

#include <cmath>

#include "io/config/speed_config.h"

namespace hullopt::io {
namespace {

void CheckSpeeds(const YamlMap& m, const std::string& key, const std::vector<double>& v, double max) {
  for (size_t i = 0; i < v.size(); ++i) {
    if (!(v[i] > 0.0))
      m.Fail(key, "speed " + std::to_string(v[i]) + " must be > 0 (resistance at rest is not defined by these methods)");
    if (v[i] > max) m.Fail(key, "speed " + std::to_string(v[i]) + " is above " + std::to_string(max));
    if (i > 0 && !(v[i] > v[i - 1])) m.Fail(key, "speeds must be strictly increasing");
  }
}

}  // namespace

std::vector<double> ResistanceConfig::MetresPerSecond(double L_m, double g_m_s2) const {
  std::vector<double> u;
  for (double kn : speeds_kn) u.push_back(kn * kMetresPerSecondPerKnot);
  for (double fn : speeds_Fn) u.push_back(fn * std::sqrt(g_m_s2 * L_m));
  return u;
}

ResistanceConfig ParseResistanceConfig(YamlMap& root, bool speeds_allowed) {
  ResistanceConfig c;
  YamlMap m = root.MapOrEmpty("resistance");
  res::ResistanceOptions& o = c.options;
  o.form_factor = m.Number("form_factor", o.form_factor);
  if (!(o.form_factor >= 1.0 && o.form_factor <= 2.0)) m.Fail("form_factor", "1 + k must be in [1, 2]");
  if (m.Has("kinematic_viscosity_m2_s")) {
    o.kinematic_viscosity_m2_s = m.Number("kinematic_viscosity_m2_s");
    if (!(o.kinematic_viscosity_m2_s >= 1e-7 && o.kinematic_viscosity_m2_s <= 1e-4))
      m.Fail("kinematic_viscosity_m2_s", "must be in [1e-7, 1e-4] m^2/s (water at 15 °C: 1.14e-6 fresh, 1.19e-6 sea)");
  }
  o.surface_points = m.Integer("surface_points", o.surface_points);
  if (o.surface_points < 4 || o.surface_points > 4096) m.Fail("surface_points", "must be in [4, 4096]");
  {
    YamlMap mi = m.MapOrEmpty("michell");
    res::MichellOptions& mo = o.michell;
    mo.depth_points = mi.Integer("depth_points", mo.depth_points);
    mo.intervals_per_wave = mi.Number("intervals_per_wave", mo.intervals_per_wave);
    mo.max_du = mi.Number("max_du", mo.max_du);
    mo.lambda_max = mi.Number("lambda_max", mo.lambda_max);
    std::string err;
    if (!mo.IsValid(&err)) {
      const std::string key = err.substr(0, err.find(' '));
      mi.Fail(key, err.substr(err.find(':') + 2));
    }
    mi.Finish();
  }
  const int given = int(m.Has("speeds_kn")) + int(m.Has("speeds_Fn")) + int(m.Has("speed_range_kn"));
  if (given > 0 && !speeds_allowed)
    m.Fail(m.Has("speeds_kn") ? "speeds_kn" : (m.Has("speeds_Fn") ? "speeds_Fn" : "speed_range_kn"),
           "speed lists belong to `hullopt resistance`; campaigns use the design speed `speed:`");
  if (given > 1) m.Fail("speeds_kn", "give one of speeds_kn, speeds_Fn, speed_range_kn");
  if (m.Has("speeds_kn")) {
    c.speeds_kn = m.Numbers("speeds_kn");
    CheckSpeeds(m, "speeds_kn", c.speeds_kn, 200.0);
  } else if (m.Has("speeds_Fn")) {
    c.speeds_Fn = m.Numbers("speeds_Fn");
    CheckSpeeds(m, "speeds_Fn", c.speeds_Fn, 5.0);
  } else if (m.Has("speed_range_kn")) {
    YamlMap r = m.Map("speed_range_kn");
    const double from = r.Number("from"), to = r.Number("to"), step = r.Number("step");
    if (!(from > 0.0)) r.Fail("from", "speed must be > 0 (resistance at rest is not defined by these methods)");
    if (!(to >= from)) r.Fail("to", "must be >= from");
    if (!(step > 0.0)) r.Fail("step", "must be > 0");
    const double n = std::floor((to - from) / step + 1e-9) + 1.0;
    if (n > 1000.0) r.Fail("step", "gives more than 1000 speeds");
    if (to > 200.0) r.Fail("to", "is above 200 kn");
    for (int i = 0; i < int(n); ++i) c.speeds_kn.push_back(from + i * step);
    r.Finish();
  }
  m.Finish();
  return c;
}

}  // namespace hullopt::io
