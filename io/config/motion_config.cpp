#include "io/config/motion_config.h"

#include "io/config/water_config.h"

#include <sstream>

#include "evaluation/trial_design.h"
#include "parametric_hull/plausibility.h"

namespace hullopt::io {
namespace {

// Documented maxima (docs/bad-inputs.md): far above any converged setting (the paper uses 40 x 14 and 20-60
// frequencies), low enough that the kernel fits in memory and a run ends in hours, not weeks.
constexpr int kMaxSections = 400;
constexpr int kMaxPanels = 100;
constexpr int kMaxFrequencies = 1000;

sk::FrequencySpec ParseFrequencies(YamlMap& f) {
  using Q = sk::FrequencySpec::Quantity;
  const std::vector<std::pair<std::string, Q>> lists = {
      {"lambda_over_L", Q::kLambdaOverL}, {"omega_rad_s", Q::kOmega}, {"omega_e_rad_s", Q::kOmegaE}};
  int given = f.Has("range") ? 1 : 0;
  for (const auto& [key, q] : lists) given += f.Has(key) ? 1 : 0;
  if (given != 1)
    f.Fail("range", "give exactly one of lambda_over_L, omega_rad_s, omega_e_rad_s (lists) or range");
  sk::FrequencySpec spec;
  std::string bad_key;
  if (f.Has("range")) {
    auto r = f.Map("range");
    const std::string qn = r.Choice("quantity", {"lambda_over_L", "omega_rad_s", "omega_e_rad_s"});
    Q q = Q::kOmegaE;
    for (const auto& [key, qq] : lists)
      if (key == qn) q = qq;
    const double from = r.Number("from"), to = r.Number("to");
    const int count = r.Integer("count");
    if (count < 1 || count > kMaxFrequencies)
      r.Fail("count", "must lie in [1, " + std::to_string(kMaxFrequencies) + "]");
    if (!(from > 0.0)) r.Fail("from", "must be > 0");
    if (!(to > 0.0)) r.Fail("to", "must be > 0");
    r.Finish();
    spec = sk::FrequencySpec::Range(q, from, to, count);
    bad_key = "range";
  } else {
    for (const auto& [key, q] : lists) {
      if (!f.Has(key)) continue;
      spec.quantity = q;
      spec.values = f.Numbers(key);
      bad_key = key;
      if (spec.values.size() > static_cast<std::size_t>(kMaxFrequencies))
        f.Fail(key, std::to_string(spec.values.size()) + " frequencies: at most " + std::to_string(kMaxFrequencies));
    }
  }
  std::string err;
  if (!spec.IsValid(&err)) f.Fail(bad_key, err);
  f.Finish();
  return spec;
}

}  // namespace

SolverConfig ParseSolverConfig(YamlMap& s, bool frequencies_required) {
  using Method = sk::RaoSolverOptions::Method;
  SolverConfig c;
  sk::RaoSolverOptions& o = c.rao;
  o.method = s.Choice("method", {"time_domain_strip", "strip_theory_stf"}, "time_domain_strip") == "strip_theory_stf"
                 ? Method::kStripTheory
                 : Method::kTimeDomainStrip;
  o.sections = s.Integer("sections", o.sections);
  if (o.sections < 2 || o.sections > kMaxSections)
    s.Fail("sections", "must lie in [2, " + std::to_string(kMaxSections) + "] (the paper uses 40)");
  o.panels = s.Integer("panels", o.panels);
  if (o.panels < 4 || o.panels % 2 != 0 || o.panels > kMaxPanels)
    s.Fail("panels", "must be even and in [4, " + std::to_string(kMaxPanels) + "] (the paper uses 14)");
  o.motion.damping_cs = s.Number("Cs", o.motion.damping_cs);
  if (o.motion.damping_cs < 0.0) s.Fail("Cs", "must be >= 0 (the paper's values are 0 to 0.15)");
  RefuseOutsideEnvelope(s, "Cs", eval::EnvelopeQuantity::kDampingCs, o.motion.damping_cs);
  double& fraction = o.marching.hydrodynamic_fraction;
  fraction = s.Number("hydrodynamic_fraction", fraction);
  if (!(fraction > 0.0 && fraction <= 1.0))
    s.Fail("hydrodynamic_fraction", "must satisfy 0 < fraction <= 1 (the paper uses 0.2 to 0.4)");
  o.path = s.Choice("path", {"periodic", "time_marching"}, "periodic") == "periodic"
               ? sk::RaoSolverOptions::Path::kPeriodic
               : sk::RaoSolverOptions::Path::kTimeMarching;
  // The step kinematics of the time-marching path (seakeeping/motions/time_scheme_registry.h). Read (and
  // recorded in the resolved config) only where it can matter, so that periodic-path configs resolve as before.
  if (o.path == sk::RaoSolverOptions::Path::kTimeMarching || s.Has("time_scheme")) {
    const auto names = sk::TimeSchemeNames();
    sk::FindTimeScheme(s.Choice("time_scheme", names, names.front()), &o.marching.scheme);
    if (o.path != sk::RaoSolverOptions::Path::kTimeMarching &&
        o.marching.scheme != sk::TimeSchemeKind::kWeightedAverageTrapezoid)
      s.Fail("time_scheme", "applies to path: time_marching only (the periodic path has no time steps); remove it "
                            "or set path: time_marching");
  }
  // Read (and recorded) only when given, so that configs without it resolve as before.
  if (s.Has("panel_spacing")) {
    auto p = s.Map("panel_spacing");
    o.spacing.end_spacing = p.Number("end_spacing", o.spacing.end_spacing);
    if (!(o.spacing.end_spacing > 0.0 && o.spacing.end_spacing <= 1.0))
      p.Fail("end_spacing", "must lie in (0, 1]: the panel length at the waterline and at corners as a fraction of "
                            "the uniform spacing (default 0.25)");
    o.spacing.grading = p.Number("grading", o.spacing.grading);
    if (!(o.spacing.grading > 0.0 && o.spacing.grading <= 10.0))
      p.Fail("grading", "must lie in (0, 10]: the growth of the spacing with the distance from the waterline or a "
                        "corner (default 0.5)");
    p.Finish();
  }
  o.interaction = s.Boolean("interaction", o.interaction);
  // Read (and recorded) only when given, so that configs without it resolve as before.
  if (s.Has("section_formulation")) {
    o.section_formulation = s.Choice("section_formulation", {"source", "direct"}, "source") == "direct"
                                ? sk::SectionFormulation::kDirect
                                : sk::SectionFormulation::kSource;
    if (o.section_formulation == sk::SectionFormulation::kDirect && o.method != Method::kStripTheory)
      s.Fail("section_formulation", "direct applies to method: strip_theory_stf only (the time-domain strip "
                                    "kernel has the source formulation)");
  }
  o.layout = s.Choice("stations", {"cell_faces", "cell_midpoints"}, "cell_faces") == "cell_midpoints"
                 ? sk::StationLayout::kCellMidpoints
                 : sk::StationLayout::kCellFaces;
  if (o.layout == sk::StationLayout::kCellFaces && o.sections < 3)
    s.Fail("sections", "must be >= 3 with stations: cell_faces");
  c.sectional_force = s.Choice("sectional_force", {"momentum", "pressure"}, "momentum") == "pressure"
                          ? sk::SectionalForce::kPressure
                          : sk::SectionalForce::kMomentum;
  // Read (and recorded) only when given, so that configs without it resolve as before.
  if (s.Has("body_potential")) {
    c.body_potential = s.Choice("body_potential", {"source_sum", "green_identity"}, "source_sum") == "green_identity"
                           ? sk::BodyPotential::kGreenIdentity
                           : sk::BodyPotential::kSourceSum;
    if (c.body_potential == sk::BodyPotential::kGreenIdentity && o.method != Method::kTimeDomainStrip)
      s.Fail("body_potential", "green_identity applies to method: time_domain_strip only (strip_theory_stf: use "
                               "section_formulation: direct)");
    if (c.body_potential == sk::BodyPotential::kGreenIdentity && c.sectional_force != sk::SectionalForce::kMomentum)
      s.Fail("body_potential", "green_identity applies to sectional_force: momentum only (the pressure form "
                               "evaluates earlier steps' source potentials on the current contour)");
  }
  if (c.sectional_force == sk::SectionalForce::kPressure && o.method != Method::kTimeDomainStrip)
    s.Fail("sectional_force", "pressure applies to method: time_domain_strip only (strip_theory_stf has its own "
                              "frequency-domain sectional force)");
  // Read (and recorded) only when given, so that configs without it resolve as before.
  if (s.Has("steady_flow")) c.steady_flow = s.Choice("steady_flow", {"on", "off"}, "off") == "on";
  // Read (and recorded) only when given, so that configs without them resolve as before (refinement on).
  if (s.Has("adaptive_grid")) c.grid.enabled = s.Boolean("adaptive_grid", c.grid.enabled);
  if (s.Has("adaptive_grid_max_passes")) {
    c.grid.max_passes = s.Integer("adaptive_grid_max_passes", c.grid.max_passes);
    if (c.grid.max_passes < 1 || c.grid.max_passes > 50) s.Fail("adaptive_grid_max_passes", "must lie in [1, 50]");
  }
  if (s.Has("adaptive_grid_max_frequencies")) {
    c.grid.max_frequencies = s.Integer("adaptive_grid_max_frequencies", c.grid.max_frequencies);
    if (c.grid.max_frequencies < 3 || c.grid.max_frequencies > kMaxFrequencies)
      s.Fail("adaptive_grid_max_frequencies", "must lie in [3, " + std::to_string(kMaxFrequencies) + "]");
  }
  if (frequencies_required || s.Has("frequencies")) {
    auto f = s.Map("frequencies");
    c.frequencies = ParseFrequencies(f);
  }
  s.Finish();
  return c;
}

double ReadKyyOverL(YamlMap& mass, double default_value) {
  const double r = mass.Number("kyy_over_L", default_value);
  if (!(r > 0.05 && r < 0.5)) mass.Fail("kyy_over_L", "must be within 0.05..0.5");
  return r;
}

double ReadKgOverT(YamlMap& mass, double default_value) {
  const double r = mass.Number("kg_over_T", default_value);
  if (!(r > 0 && r < 10)) mass.Fail("kg_over_T", "must be within 0..10");
  return r;
}

eval::MassSpec ParseMassSpec(YamlMap& m) {
  eval::MassSpec p;
  // Every key's place for the rules that need the hull (BuildDesign); a default is a placeholder in the
  // resolved tree, filled by RecordResolvedMass once the hull is known, so that the keys keep their order.
  for (const char* k : {"mass_kg", "lcg_m_from_ap", "kyy_m", "kyy_over_L", "kg_m", "kg_over_T"}) {
    const YAML::Node n = m.raw()[k];
    p.where[k] = m.Where(k) + ((n && n.IsScalar()) ? " = " + n.Scalar() : "");
  }
  YAML::Node r = m.resolved();
  auto optional = [&](const char* key) -> std::optional<double> {
    if (m.Has(key)) return m.Number(key);
    m.Skip(key);
    r[key] = YAML::Node();
    return std::nullopt;
  };
  p.mass_kg = optional("mass_kg");
  if (p.mass_kg && !(*p.mass_kg > 0.0)) m.Fail("mass_kg", "must be > 0");
  p.lcg_m_from_ap = optional("lcg_m_from_ap");
  // The campaigns' ratio keys (a campaign's best.yaml carries them) stand for kyy_m and kg_m; one of each pair.
  if (m.Has("kyy_over_L") && m.Has("kyy_m")) m.Fail("kyy_over_L", "give kyy_m or kyy_over_L, not both");
  if (m.Has("kg_over_T") && m.Has("kg_m")) m.Fail("kg_over_T", "give kg_m or kg_over_T, not both");
  if (m.Has("kyy_over_L")) {
    p.kyy_over_L = ReadKyyOverL(m, eval::kDefaultKyyOverL);
  } else {
    p.kyy_m = optional("kyy_m");
    if (p.kyy_m && !(*p.kyy_m > 0.0)) m.Fail("kyy_m", "must be > 0 (typically 0.25 L)");
  }
  if (m.Has("kg_over_T")) {
    p.kg_over_T = ReadKgOverT(m, eval::kDefaultKgOverT);
  } else {
    p.kg_m = optional("kg_m");
  }
  p.accept_mass_mismatch = m.Boolean("accept_mass_mismatch", false);
  m.Finish();
  return p;
}

void RecordResolvedMass(YAML::Node resolved, const eval::MassSpec& spec, const hull::MassProperties& mass) {
  if (!spec.mass_kg) resolved["mass_kg"] = mass.mass_kg;
  if (!spec.lcg_m_from_ap) resolved["lcg_m_from_ap"] = mass.lcg_m_from_ap;
  if (!spec.kyy_over_L && !spec.kyy_m) resolved["kyy_m"] = mass.kyy_m;
  if (!spec.kg_over_T && !spec.kg_m) resolved["kg_m"] = mass.kg_m;
}

hull::MassProperties ParseMassConfig(YamlMap& m, const hull::Hydrostatics& hs,
                                     std::vector<std::string>* warnings) {
  const eval::MassSpec spec = ParseMassSpec(m);
  const hull::MassProperties p = eval::ResolveMass(spec, hs, m.file(), warnings);
  RecordResolvedMass(m.resolved(), spec, p);
  return p;
}

}  // namespace hullopt::io
