#include "io/config/msi_objective_config.h"

#include "evaluation/oblique_design.h"

#include <cstdio>
#include <numeric>

#include "evaluation/msi_evaluator.h"
#include "evaluation/oblique_design.h"
#include "io/config/design_config.h"
#include "io/formats/input_error.h"
#include "io/config/motion_config.h"
#include "io/config/operability_config.h"
#include "io/config/resistance_config.h"
#include "io/config/seas_config.h"

namespace hullopt::io {
namespace {
std::string Deg(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}
}  // namespace

std::unique_ptr<opt::Evaluator> ReadMsiObjective(YamlMap& root, YamlMap& objective,
                                                 const opt::CampaignDefinition& campaign) {
  using Measure = eval::MsiObjectiveOptions::Measure;
  eval::MsiObjectiveOptions o;
  const std::string measure =
      objective.Choice("measure", {"msi", "rms_accel", "P_E_kW", "scatter_msi", "downtime_pct"}, "msi");
  o.measure = measure == "rms_accel"      ? Measure::kRmsAccel
              : measure == "P_E_kW"       ? Measure::kEffectivePower
              : measure == "scatter_msi"  ? Measure::kScatterMsi
              : measure == "downtime_pct" ? Measure::kDowntime
                                          : Measure::kMsi;
  const std::string pos = objective.Choice("position", {"mean", "forward", "lcg", "transom"}, "mean");
  o.position = pos == "mean" ? -1 : pos == "forward" ? 0 : pos == "lcg" ? 1 : 2;
  const bool operability = o.measure == Measure::kScatterMsi || o.measure == Measure::kDowntime;
  if (objective.Has("criterion") && o.measure != Measure::kDowntime)
    objective.Fail("criterion", "only with measure: downtime_pct");
  if (operability) {
    // The cells of the operability: block (the reader of `hullopt evaluate`) are the campaign's seas, weighted
    // by their probabilities; a seas: list is not used (accepted, so one config serves both kinds of objective).
    if (!root.Has("operability"))
      objective.Fail("measure", measure + " needs an operability: block (scatter_csv, criteria; docs/evaluate.md)");
    if (objective.Has("sea_weights"))
      objective.Fail("sea_weights", "not with measure: " + measure + " (the cells' probabilities weight them)");
    OperabilityConfig op = ParseOperability(root, {});
    root.Skip("seas");
    o.diagram = std::move(op.diagram);
    o.criteria = std::move(op.criteria);
    for (std::size_t i = 0; i < o.diagram.cells.size(); ++i) {
      o.seas.push_back(o.diagram.Sea(i));
      o.sea_weights.push_back(o.diagram.cells[i].probability);
    }
    if (o.measure == Measure::kDowntime) {
      std::vector<std::string> names = {"all"};
      for (const auto& c : o.criteria) names.push_back(c.name);
      const std::string criterion = objective.Choice("criterion", names, "all");
      for (std::size_t k = 0; k < o.criteria.size(); ++k)
        if (o.criteria[k].name == criterion) o.criterion = static_cast<int>(k);
    }
  } else {
    root.Skip("operability");  // e.g. the P_E anchor of a Pareto sweep of an operability objective
    o.seas = ReadSeas(root);
    o.sea_weights.assign(o.seas.size(), 1.0);
  }
  if (objective.Has("sea_weights")) {
    o.sea_weights = objective.Numbers("sea_weights");
    if (o.sea_weights.size() != o.seas.size())
      objective.Fail("sea_weights", "needs one weight per sea (" + std::to_string(o.seas.size()) + " seas)");
    for (double w : o.sea_weights)
      if (w < 0) objective.Fail("sea_weights", "weights must be >= 0");
    if (std::accumulate(o.sea_weights.begin(), o.sea_weights.end(), 0.0) <= 0)
      objective.Fail("sea_weights", "at least one weight must be > 0");
  }
  // Headings of the msi and rms_accel measures, with weights (>= 0, normalised); eval::MsiObjectiveOptions.
  if (objective.Has("headings_deg")) {
    if (o.measure != Measure::kMsi && o.measure != Measure::kRmsAccel)
      objective.Fail("headings_deg", "applies to measure: msi or rms_accel only");
    o.headings_deg = objective.Numbers("headings_deg");
    for (std::size_t i = 0; i < o.headings_deg.size(); ++i) {
      const double h = o.headings_deg[i];
      if (!(h >= 0.0 && h < 360.0))
        objective.Fail("headings_deg", "heading " + Deg(h) + " deg: every heading must lie in [0, 360) (180 head "
                                       "seas, 90 beam seas from starboard; docs/conventions.md)");
      for (std::size_t j = 0; j < i; ++j)
        if (o.headings_deg[j] == h) objective.Fail("headings_deg", "heading " + Deg(h) + " deg is given twice");
    }
  }
  if (objective.Has("heading_weights")) {
    if (o.headings_deg.empty()) objective.Fail("heading_weights", "applies with objective.headings_deg only");
    o.heading_weights = objective.Numbers("heading_weights");
    if (o.heading_weights.size() != o.headings_deg.size())
      objective.Fail("heading_weights", "needs one weight per heading (" + std::to_string(o.headings_deg.size()) +
                                            " headings)");
    for (double w : o.heading_weights)
      if (w < 0) objective.Fail("heading_weights", "weights must be >= 0 (they are normalised to sum 1)");
    if (std::accumulate(o.heading_weights.begin(), o.heading_weights.end(), 0.0) <= 0)
      objective.Fail("heading_weights", "at least one weight must be > 0");
  }
  const std::string headings_where = objective.Where("headings_deg");
  objective.Finish();
  o.evaluation.msi = ReadMsiOptions(root);
  YamlMap mass = root.MapOrEmpty("mass");
  const double kyy_over_L = ReadKyyOverL(mass, eval::kDefaultKyyOverL);
  const double kg_over_T = ReadKgOverT(mass, eval::kDefaultKgOverT);
  mass.Finish();
  eval::DesignBasis basis;
  o.resistance = ParseResistanceConfig(root, false).options;
  const YAML::Node& raw = root.raw();
  if (!raw["hull"] || !raw["hull"]["parametric"])
    throw InputError(root.file() + ": key 'hull.parametric': a campaign needs a parametric base hull");
  // The base design, read (and checked) once: its options are what every trial starts from.
  {
    YAML::Node base_only(YAML::NodeType::Map);
    for (const char* k : {"hull", "water", "speed", "solver"})
      if (raw[k]) base_only[k] = YAML::Clone(raw[k]);
    YamlMap check(base_only, "", root.file(), YAML::Node(YAML::NodeType::Map));
    const ParsedDesign base =
        ParseDesign(check, root.file(), "base design");  // built by eval::CheckBaseDesign
    check.Finish();
    basis = TrialBasis(base.config, root.file());
    // The base design's blocks as read (defaults filled in, paths absolute) make config.resolved.yaml complete.
    const YAML::Node read = check.resolved();
    for (const char* k : {"hull", "water", "speed", "solver"}) {
      root.Skip(k);
      if (read[k]) root.resolved()[k] = YAML::Clone(read[k]);
    }
  }
  // At speed, following and quartering seas (encounter frequency reaching 0 on the grid) are outside the strip
  // theory: the oblique path's headings must lie between beam and head seas, [90, 270].
  if (o.Oblique() && basis.speed.value > 0.0)
    for (double h : o.headings_deg)
      if (h < 90.0 || h > 270.0)
        throw InputError(headings_where + ": heading " + Deg(h) + " deg: at speed the headings must lie in [90, 270] "
                         "(beam to head seas; following and quartering seas reach encounter frequency 0, outside "
                         "the strip theory)");
  // The time-domain strip method in oblique seas: the kernel's lateral rows and a forward speed.
  if (o.Oblique() && basis.solver.rao.method == sk::RaoSolverOptions::Method::kTimeDomainStrip) {
    if (const std::string fault = eval::ObliqueTimeDomainFault(basis.solver); !fault.empty())
      throw InputError(headings_where + ": with the time-domain strip method " + fault +
                       " (or solver.method: strip_theory_stf)");
    if (!(basis.speed.value > 0.0))
      throw InputError(headings_where + ": the time-domain strip method needs a forward speed > 0 (or "
                       "solver.method: strip_theory_stf)");
  }
  basis.kyy_over_L = kyy_over_L;
  basis.kg_over_T = kg_over_T;
  std::vector<std::string> names;
  for (const auto& v : campaign.variables) names.push_back(v.name);
  return eval::MakeMsiEvaluator(std::move(basis), names, std::move(o));
}

}  // namespace hullopt::io
