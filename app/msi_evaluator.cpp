#include "app/msi_evaluator.h"

#include <cmath>
#include <numeric>

#include "app/design_case.h"
#include "io/input_error.h"
#include "io/seas_config.h"
#include "io/speed_config.h"
#include "seas/design_evaluation.h"

namespace hullopt::app {
namespace {

const std::vector<std::string> kQuantities = {"L_m", "B_m",  "T_m",  "B_overall_m", "displacement_t", "Cb",
                                              "Cp",  "Cwp", "Cvp", "Fr",          "GM_T_m",         "GM_L_m"};

class MsiEvaluator : public opt::Evaluator {
 public:
  MsiEvaluator(YAML::Node base_config, std::string file, std::vector<std::string> variables,
               std::vector<sk::SeaState> seas, std::vector<double> weights, sk::EvaluationOptions eval,
               std::string measure, int position, double kyy_over_L, double kg_over_T)
      : base_(std::move(base_config)), file_(std::move(file)), variables_(std::move(variables)),
        seas_(std::move(seas)), spectra_(sk::BuildSpectra(seas_)), weights_(std::move(weights)),
        eval_(eval), measure_(std::move(measure)), position_(position), kyy_over_L_(kyy_over_L),
        kg_over_T_(kg_over_T) {}

  opt::EvalResult Evaluate(const std::vector<double>& x) override {
    opt::EvalResult r;
    DesignCase d;
    try {
      d = Build(x);
    } catch (const io::InputError& e) {  // generator refusal or an impossible combination
      r.produced = false;
      r.error = e.what();
      return r;
    }
    const sk::RaoTable rao = ComputeDesignRaos(d, EvaluationFrequencies());
    for (const auto& w : rao.warnings) r.warning += (r.warning.empty() ? "" : "; ") + w;
    const sk::DesignEvaluation ev = sk::EvaluateDesign(rao, d.Extent(), spectra_, {}, eval_);
    double sum = 0, wsum = 0;
    for (std::size_t i = 0; i < ev.seas.size(); ++i) {
      const auto& s = ev.seas[i];
      const auto& p = position_ < 0 ? s.mean : s.positions[position_];
      const double v = measure_ == "msi" ? p.msi_pct : p.rms_accel_g;
      r.sea_values.push_back(v);
      sum += weights_[i] * v;
      wsum += weights_[i];
    }
    r.objective = sum / wsum;
    const auto& h = d.hydrostatics;
    double b_overall = 0;
    for (const auto& body : d.hull.bodies)
      for (const auto& st : body.stations)
        for (double y : st.y_m) b_overall = std::max(b_overall, 2 * (body.y_centre_m + y));
    r.quantities = {h.L_m, h.B_m, h.T_m, b_overall, h.displacement_t, h.Cb, h.Cp, h.Cwp, h.Cvp,
                    d.speed_m_s / std::sqrt(d.water.g_m_s2 * h.L_m), h.gm_t_m, h.gm_l_m};
    return r;
  }

  std::vector<std::string> SeaNames() const override {
    std::vector<std::string> n;
    for (std::size_t i = 0; i < seas_.size(); ++i) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%s_Hs%.2g_Tz%.3g", measure_ == "msi" ? "msi_pct" : "rms_accel_g",
                    seas_[i].Hs_m, seas_[i].Tz_s);
      n.push_back(buf);
    }
    return n;
  }
  std::vector<std::string> QuantityNames() const override { return kQuantities; }
  std::vector<std::string> VariableNames() const override {
    return {"L_over_B", "B_over_T", "Cb", "Cp", "Cwp", "LCB_pct_L", "LCF_pct_L", "transom_immersion",
            "transom_beam_ratio", "keel_rise", "spacing_over_L", "spacing_m", "strut_ratio", "bulb_height_ratio",
            "outrigger_length_ratio", "outrigger_L_over_B", "outrigger_B_over_T", "outrigger_offset_over_L"};
  }
  // The YAML trees are copied per evaluation; the strip kernel itself runs OpenMP-parallel inside.
  bool IsThreadSafe() const override { return false; }

 private:
  DesignCase Build(const std::vector<double>& x) const {
    YAML::Node cfg = YAML::Clone(base_);
    for (std::size_t i = 0; i < variables_.size(); ++i) cfg["hull"]["parametric"][variables_[i]] = x[i];
    io::YamlMap root(cfg, "", file_, YAML::Node(YAML::NodeType::Map));
    DesignCase d = LoadDesignCase(root, file_, "design");
    // Mass follows the design: the displacement is fixed, LCG = LCB, k_yy and KG scale with L and T.
    d.mass.mass_kg = d.hydrostatics.displacement_kg;
    d.mass.lcg_m_from_ap = d.hydrostatics.lcb_m_from_ap;
    d.mass.kyy_m = kyy_over_L_ * d.hydrostatics.L_m;
    d.mass.kg_m = kg_over_T_ * d.hydrostatics.T_m;
    d.hydrostatics = hull::ComputeHydrostatics(d.hull, d.water.rho_kg_m3, d.mass.kg_m);
    return d;
  }

  YAML::Node base_;
  std::string file_;
  std::vector<std::string> variables_;
  std::vector<sk::SeaState> seas_;
  std::vector<sk::WaveSpectrum> spectra_;
  std::vector<double> weights_;
  sk::EvaluationOptions eval_;
  std::string measure_;
  int position_;
  double kyy_over_L_, kg_over_T_;
};

}  // namespace

std::unique_ptr<opt::Evaluator> MakeMsiEvaluator(io::YamlMap& root, io::YamlMap& objective,
                                                 const opt::CampaignDefinition& campaign) {
  const std::string measure = objective.Choice("measure", {"msi", "rms_accel"}, "msi");
  const std::string pos = objective.Choice("position", {"mean", "forward", "lcg", "transom"}, "mean");
  const int position = pos == "mean" ? -1 : pos == "forward" ? 0 : pos == "lcg" ? 1 : 2;
  const std::vector<sk::SeaState> seas = io::ReadSeas(root);
  std::vector<double> weights(seas.size(), 1.0);
  if (objective.Has("sea_weights")) {
    weights = objective.Numbers("sea_weights");
    if (weights.size() != seas.size())
      objective.Fail("sea_weights", "needs one weight per sea (" + std::to_string(seas.size()) + " seas)");
    for (double w : weights)
      if (w < 0) objective.Fail("sea_weights", "weights must be >= 0");
    if (std::accumulate(weights.begin(), weights.end(), 0.0) <= 0)
      objective.Fail("sea_weights", "at least one weight must be > 0");
  }
  objective.Finish();
  sk::EvaluationOptions eval;
  eval.msi = io::ReadMsiOptions(root);
  io::YamlMap mass = root.MapOrEmpty("mass");
  const double kyy_over_L = mass.Number("kyy_over_L", 0.25);
  const double kg_over_T = mass.Number("kg_over_T", 1.0);
  if (!(kyy_over_L > 0.05 && kyy_over_L < 0.5)) mass.Fail("kyy_over_L", "must be within 0.05..0.5");
  if (!(kg_over_T > 0 && kg_over_T < 10)) mass.Fail("kg_over_T", "must be within 0..10");
  mass.Finish();
  // The base design is read (and checked) once now, so a bad base config fails before any evaluation.
  YAML::Node raw = YAML::LoadFile(root.file());
  if (!raw["hull"] || !raw["hull"]["parametric"])
    throw io::InputError(root.file() + ": key 'hull.parametric': a campaign needs a parametric base hull");
  raw.remove("mass");
  std::vector<std::string> names;
  for (const auto& v : campaign.variables) names.push_back(v.name);
  {
    YAML::Node base_only(YAML::NodeType::Map);
    for (const char* k : {"hull", "water", "speed", "solver"})
      if (raw[k]) base_only[k] = raw[k];
    io::YamlMap check(base_only, "", root.file(), YAML::Node(YAML::NodeType::Map));
    LoadDesignCase(check, root.file(), "base design");
    check.Finish();
  }
  // Record the physics blocks in the resolved config through the strict reader too.
  for (const char* k : {"hull", "water", "speed", "solver"}) root.Skip(k);
  YAML::Node base(YAML::NodeType::Map);
  for (const char* k : {"hull", "water", "speed", "solver"})
    if (raw[k]) base[k] = YAML::Clone(raw[k]);
  return std::make_unique<MsiEvaluator>(base, root.file(), names, seas, weights, eval, measure, position,
                                        kyy_over_L, kg_over_T);
}

}  // namespace hullopt::app
