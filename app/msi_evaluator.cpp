#include "app/msi_evaluator.h"

#include <cmath>
#include <numeric>
#include <stdexcept>

#include "app/design_case.h"
#include "io/input_error.h"
#include "io/resistance_config.h"
#include "io/seas_config.h"
#include "io/speed_config.h"
#include "resistance/calm_water_resistance.h"
#include "seas/design_evaluation.h"

namespace hullopt::app {
namespace {

const std::vector<std::string> kQuantities = {"L_m", "B_m",  "T_m",  "B_overall_m", "displacement_t", "Cb",
                                              "Cp",  "Cwp", "Cvp", "Fr",          "GM_T_m",         "GM_L_m",
                                              "R_T_kN", "R_W_kN", "P_E_kW"};

class MsiEvaluator : public opt::Evaluator {
 public:
  MsiEvaluator(YAML::Node base_config, std::string file, std::vector<std::string> variables,
               std::vector<sk::SeaState> seas, std::vector<double> weights, sk::EvaluationOptions eval,
               std::string measure, int position, double kyy_over_L, double kg_over_T,
               res::ResistanceOptions resistance)
      : base_(std::move(base_config)), file_(std::move(file)), variables_(std::move(variables)),
        seas_(std::move(seas)), spectra_(sk::BuildSpectra(seas_)), weights_(std::move(weights)),
        eval_(eval), measure_(std::move(measure)), position_(position), kyy_over_L_(kyy_over_L),
        kg_over_T_(kg_over_T), resistance_(resistance) {}

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
    sk::RaoTable rao;
    sk::DesignEvaluation ev;
    try {  // a non-finite RAO or response is refused where it is computed: this design is not produced
      rao = ComputeDesignRaos(d, SeaFrequencies(d));
      ev = sk::EvaluateDesign(rao, d.Extent(), spectra_, {}, eval_);
    } catch (const io::InputError& e) {
      r.produced = false;
      r.error = e.what();
      return r;
    } catch (const std::domain_error& e) {
      r.produced = false;
      r.error = e.what();
      return r;
    }
    for (const auto& w : rao.warnings) r.warning += (r.warning.empty() ? "" : "; ") + w;
    for (std::size_t i = 0; i < ev.seas.size(); ++i) {
      const auto& s = ev.seas[i];
      const auto& p = position_ < 0 ? s.mean : s.positions[position_];
      r.sea_values.push_back(measure_ == "rms_accel" ? p.rms_accel_g : p.msi_pct);
    }
    r.objective = WeightedMean(r.sea_values);
    // Calm-water resistance at the design speed (about 2 ms CPU for the default catamaran, bench_resistance).
    res::ResistanceAtSpeed rs;
    try {
      rs = res::CalmWaterResistance(d.hull, resistance_).At(d.speed_m_s, d.water.rho_kg_m3, d.water.g_m_s2);
    } catch (const std::invalid_argument& e) {
      r.produced = false;
      r.error = std::string("resistance: ") + e.what();
      return r;
    }
    if (!rs.warning.empty()) r.warning += (r.warning.empty() ? "resistance: " : "; resistance: ") + rs.warning;
    if (measure_ == "P_E_kW") r.objective = rs.P_E_W / 1e3;
    const auto& h = d.hydrostatics;
    double b_overall = 0;
    for (const auto& body : d.hull.bodies)
      for (const auto& st : body.stations)
        for (double y : st.y_m) b_overall = std::max(b_overall, 2 * (body.y_centre_m + y));
    r.quantities = {h.L_m, h.B_m, h.T_m, b_overall, h.displacement_t, h.Cb, h.Cp, h.Cwp, h.Cvp,
                    d.speed_m_s / std::sqrt(d.water.g_m_s2 * h.L_m), h.gm_t_m, h.gm_l_m,
                    rs.R_T_N / 1e3, rs.R_W_N / 1e3, rs.P_E_W / 1e3};
    return r;
  }

  double ObjectiveImplied(const std::vector<double>&, const std::vector<double>& sea_values) const override {
    // A power objective is not implied by the per-sea columns: such rows are checked by the spot recomputation.
    if (measure_ == "P_E_kW") return NAN;
    return sea_values.size() == weights_.size() ? WeightedMean(sea_values) : NAN;
  }

  std::vector<std::string> SeaNames() const override {
    std::vector<std::string> n;
    for (std::size_t i = 0; i < seas_.size(); ++i) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%s_Hs%.2g_Tz%.3g", measure_ == "rms_accel" ? "rms_accel_g" : "msi_pct",
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
  double WeightedMean(const std::vector<double>& v) const {
    double sum = 0, wsum = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      sum += weights_[i] * v[i];
      wsum += weights_[i];
    }
    return sum / wsum;
  }
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
  res::ResistanceOptions resistance_;
};

}  // namespace

std::unique_ptr<opt::Evaluator> MakeMsiEvaluator(io::YamlMap& root, io::YamlMap& objective,
                                                 const opt::CampaignDefinition& campaign) {
  const std::string measure = objective.Choice("measure", {"msi", "rms_accel", "P_E_kW"}, "msi");
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
  const res::ResistanceOptions resistance = io::ParseResistanceConfig(root, false).options;
  // The base design is read (and checked) once now, so a bad base config fails before any evaluation.
  YAML::Node raw = YAML::Clone(root.raw());
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
                                        kyy_over_L, kg_over_T, resistance);
}

}  // namespace hullopt::app
