#include "io/config/design_config.h"

#include <sstream>

#include "evaluation/design_spec.h"
#include "evaluation/oblique_design.h"
#include "io/config/motion_config.h"
#include "io/config/water_config.h"
#include "io/formats/input_error.h"

namespace hullopt::io {

std::string ParseDesignName(YamlMap& root, const std::string& fallback) {
  const std::string name = root.String("name", fallback);
  if (name.empty()) root.Fail("name", "must not be empty");
  return name;
}

ParsedDesign ParseDesign(YamlMap& root, const std::string& config_file, const std::string& name,
                         const DesignReadOptions& o) {
  ParsedDesign p;
  eval::DesignSpec& s = p.spec;
  s.name = name;
  s.source = config_file;
  s.water = ParseWater(root);
  const HullOptions hull_opts = ParseHullConfig(root, s.water);
  const SpeedOptions speed = o.read_speed ? ParseSpeed(root, true) : SpeedOptions{};
  if (o.name_after_hull) s.name = o.name_after_hull(hull_opts);
  s.has_speed = o.read_speed;
  s.speed = speed;
  s.hull.parametric = hull_opts.source == HullOptions::Source::kParametric;
  s.hull.variables = hull_opts.design;
  s.hull.attitude = hull_opts.attitude;
  if (o.roll) p.roll_damping = "ikeda";  // the default, also without a solver block
  if (o.frequencies_required || root.Has("solver")) {
    YamlMap sm = root.Map("solver");
    s.has_frequencies = sm.Has("frequencies");
    if (o.impulsive_kernel)
      p.kernel = sm.Choice("kernel", {"transient_green", "impulsive"}, "transient_green");
    else if (sm.Has("kernel"))
      sm.Choice("kernel", {"transient_green"}, "transient_green");
    if (o.headings && sm.Has("headings_deg")) {
      p.headings_deg = sm.Numbers("headings_deg");
      for (double h : p.headings_deg)
        if (!(h >= 0.0 && h < 360.0)) {
          std::ostringstream os;
          os << "heading " << h << " deg: every heading must lie in [0, 360) (180 head seas, 90 beam seas from "
             << "starboard; docs/conventions.md)";
          sm.Fail("headings_deg", os.str());
        }
    }
    // Viscous roll damping: read with headings or with a command that computes roll (its default then
    // recorded), refused with headings asked for but not given.
    if (o.headings || o.roll) {
      const char* given = sm.Has("roll_damping") ? "roll_damping"
                          : sm.Has("roll_amplitude_deg") ? "roll_amplitude_deg"
                                                         : nullptr;
      if (!p.headings_deg.empty() || o.roll || given) {
        p.roll_damping = sm.Choice("roll_damping", {"ikeda", "none"}, "ikeda");
        p.roll_amplitude_deg = sm.Number("roll_amplitude_deg", 5.0);
        if (!(p.roll_amplitude_deg > 0.0 && p.roll_amplitude_deg <= 28.0))
          sm.Fail("roll_amplitude_deg", "must lie in (0, 28] deg (the quadratic damping is linearised at this roll "
                                        "amplitude; 5 deg is the default)");
        if (p.headings_deg.empty() && !o.roll)
          sm.Fail(given, "applies with solver.headings_deg only (roll is solved in oblique seas)");
      }
    }
    // Evaluations in seas choose their own frequency grid, so solver.frequencies is optional there.
    s.solver = ParseSolverConfig(sm, o.frequencies_required);
    // The time-domain strip method in oblique seas needs the kernel's lateral rows: the transient Green
    // function on full sections, momentum form, source sum, all bodies sharing the strips.
    if (!p.headings_deg.empty() && s.solver.rao.method == sk::RaoSolverOptions::Method::kTimeDomainStrip &&
        (p.kernel == "impulsive" || !eval::ObliqueTimeDomainFault(s.solver).empty()))
      sm.Fail("headings_deg",
              "with the time-domain strip method needs kernel: transient_green, sectional_force: momentum, "
              "body_potential: source_sum and interaction on (or solver.method: strip_theory_stf)");
    if (!p.headings_deg.empty()) {  // roll needs the centre of gravity's height: no default KG with headings
      const YAML::Node raw = root.raw();
      const YAML::Node mass = raw["mass"];
      if (!(mass && mass.IsMap() && (mass["kg_m"] || mass["kg_over_T"])))
        sm.Fail("headings_deg",
                "roll needs the height of the centre of gravity: give mass.kg_m (or mass.kg_over_T)");
    }
    if (p.kernel == "impulsive" && s.solver.body_potential != sk::BodyPotential::kSourceSum)
      sm.Fail("body_potential",
              "the impulsive stand-in kernel has the source sum only (use kernel: "
              "transient_green)");
    if (p.kernel == "impulsive" && s.solver.sectional_force == sk::SectionalForce::kPressure)
      sm.Fail("sectional_force",
              "the impulsive stand-in kernel has the momentum form only (use kernel: "
              "transient_green)");
  }
  if (o.roll) {  // roll needs the centre of gravity's height: no default KG
    const YAML::Node mass = root.raw()["mass"];
    if (!(mass && mass.IsMap() && (mass["kg_m"] || mass["kg_over_T"])))
      throw InputError(root.Where(o.roll_key.substr(0, o.roll_key.find('.'))) + ": " + o.roll_key +
                       " computes roll, which needs the height of the centre of gravity: give mass.kg_m (or "
                       "mass.kg_over_T)");
  }
  YamlMap mass_map = root.MapOrEmpty("mass");
  if (!p.headings_deg.empty() || o.roll) {
    if (mass_map.Has("kxx_m")) {
      p.kxx_m = mass_map.Number("kxx_m");
      if (!(*p.kxx_m > 0.0)) mass_map.Fail("kxx_m", "must be > 0 (typically 0.35 to 0.4 of the overall beam)");
    }
  }
  s.mass = ParseMassSpec(mass_map);
  p.resolved_mass = mass_map.resolved();
  p.config = {s.water, hull_opts, speed, s.solver, s.has_frequencies};
  return p;
}

void ReadHullFile(ParsedDesign& p) {
  if (p.spec.hull.parametric || !p.spec.hull.given.bodies.empty()) return;
  p.spec.hull.given_warnings.clear();
  p.spec.hull.given = LoadHull(p.config.hull, p.spec.source, &p.spec.hull.given_warnings);
}

eval::DesignCase BuildParsedDesign(ParsedDesign& p) {
  ReadHullFile(p);
  eval::DesignCase d = eval::BuildDesign(p.spec);
  RecordResolvedMass(p.resolved_mass, p.spec.mass, d.mass);
  return d;
}

eval::DesignCase LoadDesignCase(YamlMap& root, const std::string& config_file, const std::string& name,
                                bool read_speed, DesignConfig* config) {
  DesignReadOptions o;
  o.read_speed = read_speed;
  ParsedDesign p = ParseDesign(root, config_file, name, o);
  eval::DesignCase d = BuildParsedDesign(p);
  if (config) *config = p.config;
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
