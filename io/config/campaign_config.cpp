#include "io/config/campaign_config.h"

namespace hullopt::io {

// Documented maximum of explore samples and optimizer evaluations (docs/bad-inputs.md): a campaign of this size
// already takes days at ~1 s per design.
constexpr int kMaxSamples = 1000000;

CampaignConfig ReadCampaignConfig(YamlMap& root, const YAML::Node& raw_root, CampaignCommand command,
                                  std::optional<YamlMap>* block_out) {
  CampaignConfig cfg;
  const bool explore = command == CampaignCommand::kExplore;
  cfg.block = (explore && root.Has("explore")) ? "explore" : "optimize";
  if (!root.Has(cfg.block)) {
    throw InputError(root.file() + ": missing the '" + cfg.block + "' block (" +
                     (explore ? "explore reads 'explore:' or 'optimize:'" : "see docs/commands/optimize.md") + ")");
  }
  if (explore && cfg.block == "explore") root.Skip("optimize");
  if (!explore) root.Skip("explore");
  YamlMap b = root.Map(cfg.block);
  opt::CampaignDefinition& d = cfg.definition;

  // Keys of the other command are accepted (one config for both) and not recorded.
  if (explore) {
    for (const char* k : {"algorithm", "max_evaluations", "xtol_rel", "ftol_rel", "starts", "penalty_weight",
                          "polish", "pareto"})
      b.Skip(k);
    cfg.explore.samples = b.Integer("samples", cfg.explore.samples);
    cfg.explore.method = b.Choice("method", {"sobol", "lhs"}, cfg.explore.method);
    if (cfg.explore.samples < 1 || cfg.explore.samples > kMaxSamples)
      b.Fail("samples", "must lie in [1, " + std::to_string(kMaxSamples) + "]");
  } else {
    b.Skip("samples");
    b.Skip("method");
    d.algorithm = b.String("algorithm", d.algorithm);
    d.stopping.max_evaluations = b.Integer("max_evaluations", d.stopping.max_evaluations, 1, kMaxSamples);
    d.stopping.xtol_rel = b.Number("xtol_rel", d.stopping.xtol_rel);
    d.stopping.ftol_rel = b.Number("ftol_rel", d.stopping.ftol_rel);
    d.starts = b.Integer("starts", d.starts, 1, 1000);
    d.penalty_weight = b.Number("penalty_weight", d.penalty_weight);
    if (b.Has("polish")) {
      YamlMap polish = b.Map("polish");
      d.polish_algorithm = polish.String("algorithm");
      d.polish_max_evaluations = polish.Integer("max_evaluations", d.polish_max_evaluations, 1, kMaxSamples);
      polish.Finish();
    } else {
      b.Skip("polish");
    }
  }
  const int seed = b.Integer("seed", 1);
  if (seed < 0) b.Fail("seed", "must be >= 0");
  d.seed = static_cast<std::uint64_t>(seed);
  d.feasibility_tol = b.Number("feasibility_tol", d.feasibility_tol);

  YamlMap vars = b.Map("variables");
  YamlMap start = b.MapOrEmpty("start");
  const YAML::Node parametric =
      (raw_root["hull"] && raw_root["hull"].IsMap()) ? raw_root["hull"]["parametric"] : YAML::Node();
  for (const auto& name : vars.Keys()) {
    const auto bounds = vars.Numbers(name);
    if (bounds.size() != 2)
      vars.Fail(name, "must be [lower, upper], got " + std::to_string(bounds.size()) + " numbers");
    opt::DesignVariable v;
    v.name = name;
    v.lower = bounds[0];
    v.upper = bounds[1];
    if (start.Has(name)) {
      v.start = start.Number(name);
      cfg.start_source.push_back(cfg.block + ".start");
    } else if (parametric && parametric.IsMap() && parametric[name] && parametric[name].IsScalar()) {
      try {
        v.start = parametric[name].as<double>();
      } catch (const YAML::Exception&) {
        throw InputError(root.file() + ": key 'hull.parametric." + name + "' must be a number");
      }
      cfg.start_source.push_back("hull.parametric");
    } else {
      vars.Fail(name, "has no base value: give it in hull.parametric." + name + " or " + cfg.block +
                          ".start." + name);
    }
    d.variables.push_back(v);
  }
  for (const auto& k : start.Keys()) {
    bool found = false;
    for (const auto& v : d.variables) found = found || v.name == k;
    if (!found) start.Fail(k, "is not a free variable (listed in " + cfg.block + ".variables)");
  }

  YamlMap cons = b.MapOrEmpty("constraints");
  for (const auto& key : cons.Keys()) {
    opt::Constraint c;
    c.key = key;
    if (!opt::ParseConstraintKey(key, &c.quantity, &c.kind)) {
      cons.Fail(key,
                "constraint keys are <quantity>_max or <quantity>_min, optionally followed by a unit "
                "(e.g. L_max_m, Cvp_min)");
    }
    c.limit = cons.Number(key);
    d.constraints.push_back(c);
  }
  b.Skip("objective");  // read by the evaluator factory through *block_out
  if (block_out != nullptr) block_out->emplace(b);
  return cfg;
}

void ValidateCampaign(const CampaignConfig& config, CampaignCommand command, const std::string& file) {
  std::string error;
  if (!config.definition.IsValid(&error)) throw InputError(file + ": " + config.block + ": " + error);
  if (command == CampaignCommand::kExplore && config.explore.method == "sobol" &&
      config.definition.variables.size() > 16) {
    throw InputError(file + ": " + config.block + ".method = sobol: supports at most 16 variables, got " +
                     std::to_string(config.definition.variables.size()) + " (use method: lhs)");
  }
}

}  // namespace hullopt::io
