#include "io/config/hull_config.h"

#include <cmath>
#include <stdexcept>

#include "evaluation/design_spec.h"
#include "evaluation/hull_plausibility.h"
#include "io/config/config_path.h"
#include "io/formats/input_limits.h"
#include "io/formats/offsets_csv.h"
#include "io/formats/stl_reader.h"
#include "parametric_hull/hull_generator.h"
#include "parametric_hull/section_geometry.h"

namespace hullopt::io {
namespace {

// Default stations for slicing an STL.
constexpr int kDefaultStlStations = 41;
// Resampled or sliced stations: the paper's hulls need 21-41; beyond this the offsets file only grows.
constexpr int kMaxStations = 1001;

hull::DesignVariables ParseParametric(YamlMap& p, const WaterOptions& water) {
  hull::DesignVariables d;
  const std::string type = p.Choice("type", {"monohull", "catamaran", "swath", "trihull"});
  d.type = hull::ParseHullType(type);
  const std::string default_style = d.type == hull::HullType::kSwath ? "swath_bulb" : "round_bilge";
  d.section_style = hull::ParseSectionStyle(
      p.Choice("section_style", {"round_bilge", "hard_chine", "swath_bulb"}, default_style));
  d.rho_kg_m3 = water.rho_kg_m3;
  for (const auto& f : hull::DesignVariableFields()) {
    if (!f.parametric_key) continue;
    d.*f.field = f.required ? p.Number(f.name) : p.Number(f.name, d.*f.field);
  }
  d.stations = p.Integer("stations", d.stations);
  d.section_points = p.Integer("section_points", d.section_points);
  d.on_infeasible = p.Choice("on_infeasible", {"refuse", "nearest"}, "refuse") == "nearest"
                        ? hull::OnInfeasible::kNearest
                        : hull::OnInfeasible::kRefuse;
  p.Finish();
  if (const auto bad = d.FirstInvalid()) {
    // Point at the key when the rule is about one of this map's keys.
    if (p.Has(bad->field)) p.Fail(bad->field, bad->rule);
    throw InputError(p.Where(p.Has("Cb") ? "Cb" : "type") + ": " + bad->Message());
  }
  return d;
}

hull::RunningAttitude ParseAttitude(YamlMap& h) {
  hull::RunningAttitude a;
  if (!h.Has("attitude")) return a;
  YamlMap m = h.Map("attitude");
  a.sinkage_m = m.Number("sinkage_m", 0.0);
  a.trim_deg = m.Number("trim_deg", 0.0);
  if (std::fabs(a.trim_deg) > hull::kMaxTrimDeg)
    m.Fail("trim_deg", "|trim| must be <= " + std::to_string(int(hull::kMaxTrimDeg)) +
                           " deg (+ bow up; stations stay vertical, a small-angle model)");
  m.Finish();
  return a;
}

}  // namespace

HullOptions ParseHullConfig(YamlMap& root, const WaterOptions& water) {
  YamlMap h = root.Map("hull");
  HullOptions o;
  const int sources = int(h.Has("parametric")) + int(h.Has("offsets_csv")) + int(h.Has("stl"));
  if (sources != 1)
    throw InputError(root.Where("hull") + ": give exactly one of parametric, offsets_csv, stl (found " +
                     std::to_string(sources) + ")");
  if (h.Has("parametric")) {
    o.source = HullOptions::Source::kParametric;
    YamlMap p = h.Map("parametric");
    o.design = ParseParametric(p, water);
    o.design.spacing_m = h.Number("spacing_m", 0.0);
    if (o.design.spacing_m < 0.0) h.Fail("spacing_m", "must be >= 0 (0 = use parametric.spacing_over_L)");
    const int hulls = h.Integer(
        "hulls",
        o.design.type == hull::HullType::kCatamaran || o.design.type == hull::HullType::kSwath ? 2 : 1);
    const int expected =
        o.design.type == hull::HullType::kCatamaran || o.design.type == hull::HullType::kSwath ? 2 : 1;
    if (hulls != expected)
      h.Fail("hulls", "must be " + std::to_string(expected) + " for a " + hull::ToString(o.design.type) +
                          " (trihull outriggers are not counted)");
    o.hulls = hulls;
    o.attitude = ParseAttitude(h);
    h.Finish();
    return o;
  }
  o.source = h.Has("stl") ? HullOptions::Source::kStl : HullOptions::Source::kOffsetsCsv;
  o.file = ConfigFilePath(h, h.Has("stl") ? "stl" : "offsets_csv");
  o.draught_m = h.Number("draught_m");
  if (!(o.draught_m > 0.0)) h.Fail("draught_m", "must be > 0 m");
  o.hulls = h.Integer("hulls", 1);
  if (o.hulls != 1 && o.hulls != 2) h.Fail("hulls", "must be 1 (monohull) or 2 (catamaran/SWATH demihulls)");
  o.spacing_m = h.Number("spacing_m", 0.0);
  if (o.hulls == 2 && !(o.spacing_m > 0.0))
    h.Fail("spacing_m", "must be > 0 m (demihull centreline spacing) when hulls = 2");
  if (o.hulls == 1 && o.spacing_m != 0.0) h.Fail("spacing_m", "only applies to hulls = 2");
  o.stations = h.Integer("stations", o.source == HullOptions::Source::kStl ? kDefaultStlStations : 0);
  if (o.stations != 0 && (o.stations < 3 || o.stations > kMaxStations))
    h.Fail("stations", "must be 0 (keep the file's stations) or in [3, " + std::to_string(kMaxStations) + "]");
  o.length_m = h.Number("length_m", 0.0);
  if (o.length_m < 0.0) h.Fail("length_m", "must be >= 0 m (0 = span of the wetted stations)");
  for (const char* k : {"draught_m", "spacing_m", "length_m"})
    if (h.Has(k) && std::fabs(h.Number(k)) > kMaxCoordinate_m)
      h.Fail(k, "is not a hull dimension (at most " + std::to_string(int(kMaxCoordinate_m)) + " m)");
  o.attitude = ParseAttitude(h);
  h.Finish();
  return o;
}

hull::HullForm LoadHull(const HullOptions& o, const std::string& config_file, std::vector<std::string>* warnings) {
  auto keep = [&](const std::vector<std::string>& w) {
    if (warnings) warnings->insert(warnings->end(), w.begin(), w.end());
  };
  if (o.source == HullOptions::Source::kParametric)
    return eval::GenerateParametricHull(o.design, config_file, warnings);
  hull::HullForm h;
  h.draught_m = o.draught_m;
  h.length_m = o.length_m;
  hull::Demihull body;
  if (o.source == HullOptions::Source::kOffsetsCsv) {
    h.type = "offsets";
    body = ReadOffsetsCsv(o.file, o.draught_m);
  } else {
    h.type = "stl";
    body = SliceStl(ReadStl(o.file), o.stations, o.draught_m, o.file);
  }
  body.role = o.hulls == 2 ? "demihull" : "main";
  body.y_centre_m = o.hulls == 2 ? 0.5 * o.spacing_m : 0.0;
  h.bodies = {body};
  if (o.stations > 0 && o.source == HullOptions::Source::kOffsetsCsv) h = hull::Resample(h, o.stations);
  keep(eval::CheckHull(h, o.file));
  return h;
}

hull::HullForm ApplyHullAttitude(const HullOptions& o, const hull::HullForm& at_rest, double pivot_x_m,
                                 const std::string& config_file) {
  hull::RunningAttitude a = o.attitude;
  a.pivot_x_m = pivot_x_m;
  try {
    return hull::ApplyRunningAttitude(at_rest, a);
  } catch (const std::logic_error& e) {  // invalid_argument and domain_error
    throw InputError(config_file + ": key 'hull.attitude': " + e.what());
  }
}

}  // namespace hullopt::io
