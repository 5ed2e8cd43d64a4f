#include "io/config/msi_objective_config.h"

#include <numeric>

#include "evaluation/msi_evaluator.h"
#include "io/config/design_config.h"
#include "io/formats/input_error.h"
#include "io/config/motion_config.h"
#include "io/config/operability_config.h"
#include "io/config/resistance_config.h"
#include "io/config/seas_config.h"

namespace hullopt::io {

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
  basis.kyy_over_L = kyy_over_L;
  basis.kg_over_T = kg_over_T;
  std::vector<std::string> names;
  for (const auto& v : campaign.variables) names.push_back(v.name);
  return eval::MakeMsiEvaluator(std::move(basis), names, std::move(o));
}

}  // namespace hullopt::io
