#include "evaluation/msi_evaluator.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "evaluation/design_resolution_check.h"
#include "evaluation/design_spec.h"
#include "evaluation/input_error.h"
#include "evaluation/oblique_design.h"
#include "evaluation/oblique_point_response.h"
#include "evaluation/validity_envelope.h"
#include "optimizer/evaluation_cost.h"

namespace hullopt::eval {
namespace {

const std::vector<std::string> kQuantities = {"L_m", "B_m",  "T_m",  "B_overall_m", "displacement_t", "Cb",
                                              "Cp",  "Cwp", "Cvp", "Fr",          "GM_T_m",         "GM_L_m",
                                              "R_T_kN", "R_W_kN", "P_E_kW"};

class MsiEvaluator : public opt::Evaluator, public ResolutionCheckable {
 public:
  MsiEvaluator(DesignBasis basis, std::vector<const hull::DesignVariableField*> fields, MsiObjectiveOptions o)
      : basis_(std::move(basis)), fields_(std::move(fields)), o_(std::move(o)), spectra_(sk::BuildSpectra(o_.seas)) {
    std::string err;
    if (!o_.IsValid(&err)) throw std::invalid_argument("MSI objective: " + err);
    if (o_.Oblique()) {  // normalised weights (equal when none are given)
      heading_weights_ = o_.heading_weights.empty() ? std::vector<double>(o_.headings_deg.size(), 1.0)
                                                    : o_.heading_weights;
      double sum = 0.0;
      for (double w : heading_weights_) sum += w;
      for (double& w : heading_weights_) w /= sum;
    }
    if (!IsOperability()) {
      grid_spectra_ = spectra_;
      return;
    }
    std::vector<sk::SeaState> cells;
    for (std::size_t i = 0; i < o_.diagram.cells.size(); ++i) cells.push_back(o_.diagram.Sea(i));
    grid_spectra_ = sk::BuildSpectra(cells);
  }
  const DesignBasis& basis() const { return basis_; }

  opt::EvalResult Evaluate(const std::vector<double>& x) override {
    opt::EvalResult r;
    DesignCase d;
    try {
      d = BuildTrialDesign(basis_, fields_, x);
    } catch (const InputError& e) {  // generator refusal or an impossible combination
      r.produced = false;
      r.error = e.what();
      return r;
    }
    sk::RaoTable rao;
    sk::DesignEvaluation ev;
    sk::OperabilityResult op;
    try {  // a non-finite RAO or response is refused where it is computed: this design is not produced
      if (o_.Oblique()) {
        r.sea_values = ObliqueSeaValues(d, &rao.warnings);
      } else {
        rao = DesignRaos(d);
        const opt::CostTimer timer(opt::CostStage::kSeas);
        if (IsOperability())
          op = sk::EvaluateOperability(rao, d.Extent(), o_.diagram, o_.criteria, {}, o_.evaluation);
        else
          ev = sk::EvaluateDesign(rao, d.Extent(), spectra_, {}, o_.evaluation);
      }
    } catch (const InputError& e) {
      r.produced = false;
      r.error = e.what();
      return r;
    } catch (const std::invalid_argument& e) {  // EvaluateOperability's refusal of a response
      r.produced = false;
      r.error = e.what();
      return r;
    } catch (const std::domain_error& e) {
      r.produced = false;
      r.error = e.what();
      return r;
    }
    for (const auto& w : rao.warnings) r.warning += (r.warning.empty() ? "" : "; ") + w;
    for (const auto& w : ResponseEnvelopeWarnings(ev, d.water.g_m_s2)) r.warning += (r.warning.empty() ? "" : "; ") + w;
    for (std::size_t i = 0; i < ev.seas.size(); ++i) {
      const auto& s = ev.seas[i];
      const auto& p = o_.position < 0 ? s.mean : s.positions[o_.position];
      r.sea_values.push_back(o_.measure == Measure::kRmsAccel ? p.rms_accel_g : p.msi_pct);
    }
    for (const auto& c : op.cells)
      r.sea_values.push_back(o_.position < 0 ? c.evaluation.mean.msi_pct : c.evaluation.positions[o_.position].msi_pct);
    r.objective = WeightedMean(r.sea_values);  // kScatterMsi: the weights are the cells' probabilities
    if (o_.measure == Measure::kDowntime)
      r.objective = 100.0 - (o_.criterion < 0 ? op.all_criteria_time_pct : op.criterion_time_pct[o_.criterion]);
    // Calm-water resistance at the design speed (about 2 ms CPU for the default catamaran, bench_resistance).
    res::ResistanceAtSpeed rs;
    try {
      const opt::CostTimer timer(opt::CostStage::kResistance);
      rs = res::CalmWaterResistance(d.hull, o_.resistance).At(d.speed_m_s, d.water.rho_kg_m3, d.water.g_m_s2);
    } catch (const std::invalid_argument& e) {
      r.produced = false;
      r.error = std::string("resistance: ") + e.what();
      return r;
    }
    if (!rs.warning.empty()) r.warning += (r.warning.empty() ? "resistance: " : "; resistance: ") + rs.warning;
    if (o_.measure == Measure::kEffectivePower) r.objective = rs.P_E_W / 1e3;
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

  sk::ResolutionCheck CheckResolution(const std::vector<double>& x, int factor,
                                      const sk::ResolutionCheckOptions& options) override {
    const DesignCase d = BuildTrialDesign(basis_, fields_, x);
    const sk::RaoTable rao = DesignRaos(d);
    sk::DesignEvaluation ev;
    try {
      ev = sk::EvaluateDesign(rao, d.Extent(), spectra_, {}, o_.evaluation);
    } catch (const std::exception& e) {
      throw InputError("design '" + d.name + "': " + e.what());
    }
    return CheckDesignResolution(d, rao, ev, spectra_, {}, o_.evaluation, factor, options);
  }

  double ObjectiveImplied(const std::vector<double>&, const std::vector<double>& sea_values) const override {
    // A power objective is not implied by the per-sea columns: such rows are checked by the spot recomputation.
    // Nor is the time a criterion is met (it may be a limit on another measure than the per-cell MSI columns).
    if (o_.measure == Measure::kEffectivePower || o_.measure == Measure::kDowntime) return NAN;
    return sea_values.size() == o_.sea_weights.size() ? WeightedMean(sea_values) : NAN;
  }

  std::vector<std::string> SeaNames() const override {
    std::vector<std::string> n;
    for (std::size_t i = 0; i < o_.seas.size(); ++i) {
      char buf[96];
      if (IsOperability())  // scatter cells: Hs 10.5 and 11.5 must not both print as 1e+01
        std::snprintf(buf, sizeof buf, "msi_pct_Hs%.4g_%s%.4g", o_.diagram.cells[i].Hs_m,
                      o_.diagram.period_is_tp ? "Tp" : "Tz", o_.diagram.cells[i].period_s);
      else
        std::snprintf(buf, sizeof buf, "%s_Hs%.2g_Tz%.3g", o_.measure == Measure::kRmsAccel ? "rms_accel_g" : "msi_pct",
                      o_.seas[i].Hs_m, o_.seas[i].Tz_s);
      n.push_back(buf);
    }
    return n;
  }
  // Short enough for a y axis: "mean MSI over 2 seas [%]", "rms accel. LCG [g]".
  std::string ObjectiveLabel() const override {
    if (o_.measure == Measure::kEffectivePower) return "P_E at the design speed [kW]";
    if (o_.measure == Measure::kDowntime)
      return "time criterion " + (o_.criterion < 0 ? std::string("(all)") : o_.criteria[o_.criterion].name) +
             " not met [%]";
    if (o_.measure == Measure::kScatterMsi)
      return std::string("scatter-weighted MSI ") + (o_.position < 0 ? "mean" : kPositionNames[o_.position]) + " [%]";
    const char* const* kPositions = kPositionNames;
    const bool accel = o_.measure == Measure::kRmsAccel;
    std::string label = o_.position < 0 ? std::string(accel ? "mean rms accel." : "mean MSI")
                                        : std::string(accel ? "rms accel. " : "MSI ") + kPositions[o_.position];
    if (o_.seas.size() > 1) label += " over " + std::to_string(o_.seas.size()) + " seas";
    if (o_.Oblique()) label += (o_.seas.size() > 1 ? ", " : " over ") + std::to_string(o_.headings_deg.size()) + " headings";
    return label + (accel ? " [g]" : " [%]");
  }
  std::string ObjectiveMethod() const override {
    if (o_.measure != Measure::kMsi && o_.measure != Measure::kRmsAccel) return "";
    if (!o_.Oblique())
      return "head seas (180 deg) by the design's own solver (solver.method, the time-domain strip method by "
             "default)";
    std::string m = "weighted over the headings";
    for (std::size_t h = 0; h < o_.headings_deg.size(); ++h) {
      char b[64];
      std::snprintf(b, sizeof b, "%s %g deg (weight %.4g)", h ? "," : "", o_.headings_deg[h], heading_weights_[h]);
      m += b;
    }
    const bool td = basis_.solver.rao.method == sk::RaoSolverOptions::Method::kTimeDomainStrip;
    return m + ", every heading (180 included) by " +
           (td ? std::string("the time-domain strip method (periodic steady state on the kernel with its lateral "
                             "rows; at 180 deg the head-sea path's heave and pitch)")
               : std::string("the oblique-sea strip theory (STF)")) +
           " with the design's Cs in heave and pitch and potential roll damping, on the sea frequencies without "
           "adaptive refinement, so that the headings are compared by one method; weights normalised to sum 1";
  }
  std::vector<std::string> QuantityNames() const override { return kQuantities; }
  std::vector<std::string> VariableNames() const override {
    std::vector<std::string> names;
    for (const auto& f : hull::DesignVariableFields())
      if (f.campaign_variable) names.push_back(f.name);
    return names;
  }
  // Evaluate changes nothing of the evaluator and the chain below it keeps its scratch per thread, so designs
  // may be evaluated concurrently (explore's samples, optimize's multistart runs); the strip kernel's own
  // parallel loops then run on the design's thread.
  bool IsThreadSafe() const override { return true; }

 private:
  // The per-sea values Σ_h w_h v_h by the design's method in oblique seas (MsiObjectiveOptions::headings_deg): v_h
  // the MSI [%] or rms vertical acceleration [g] at `position` (the mean of the three standard positions for
  // -1), all on the hull's centreline at the CG's height, in the long-crested sea travelling at heading h.
  // `warnings` receives what the head-sea path's table would carry: the generator's adjustments, the input's
  // warnings, the strip kernel's and the method's validity range.
  std::vector<double> ObliqueSeaValues(const DesignCase& d, std::vector<std::string>* warnings) const {
    const std::vector<double> omega = SeaFrequencies(d);
    sk::ObliqueStripResult result;
    *warnings = d.hull.adjustments;
    warnings->insert(warnings->end(), d.input_warnings.begin(), d.input_warnings.end());
    {
      const opt::CostTimer timer(opt::CostStage::kObliqueSolve);
      result = SolveObliqueDesign(d, d.speed_m_s, omega, o_.headings_deg, DefaultRollRadiusOfGyration(d.hull), {},
                                  warnings);
    }
    const opt::CostTimer timer(opt::CostStage::kSeas);
    std::vector<ShipPoint> points;
    for (const auto& p : sk::StandardPassengerPositions(d.Extent().cg_to_transom_m))
      points.push_back({p.name, p.x_from_cg_m, 0.0, 0.0});
    const double g = d.water.g_m_s2;
    std::vector<double> values(spectra_.size(), 0.0);
    for (std::size_t h = 0; h < o_.headings_deg.size(); ++h) {
      for (std::size_t s = 0; s < spectra_.size(); ++s) {
        const ObliqueSeaStatistics st = ObliqueStatisticsInSea(result, h, g, spectra_[s], points, o_.evaluation);
        auto value = [&](const PointSeaStatistics& q) {
          return o_.measure == Measure::kRmsAccel ? q.rms_vertical_accel_m_s2 / g : q.msi_pct;
        };
        double v = 0.0;
        if (o_.position < 0)
          v = (value(st.points[0]) + value(st.points[1]) + value(st.points[2])) / 3.0;
        else
          v = value(st.points[static_cast<std::size_t>(o_.position)]);
        values[s] += heading_weights_[h] * v;
      }
    }
    return values;
  }
  double WeightedMean(const std::vector<double>& v) const {
    double sum = 0, wsum = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      sum += o_.sea_weights[i] * v[i];
      wsum += o_.sea_weights[i];
    }
    return sum / wsum;
  }
  using Measure = MsiObjectiveOptions::Measure;
  static constexpr const char* kPositionNames[] = {"forward", "LCG", "transom"};
  // The design's RAOs on its grid, refined (solver.adaptive_grid) until the MSI of the objective's seas (or
  // scatter cells) converges.
  sk::RaoTable DesignRaos(const DesignCase& d) const {
    const GridSeas seas{grid_spectra_, d.Extent(), {}, o_.evaluation};
    return ComputeDesignRaos(d, SeaFrequencies(d), -1.0, &seas);
  }
  bool IsOperability() const { return o_.measure == Measure::kScatterMsi || o_.measure == Measure::kDowntime; }
  DesignBasis basis_;
  std::vector<const hull::DesignVariableField*> fields_;
  MsiObjectiveOptions o_;
  std::vector<sk::WaveSpectrum> spectra_;
  std::vector<sk::WaveSpectrum> grid_spectra_;  // what the frequency grid must resolve: the seas or the cells
  std::vector<double> heading_weights_;         // the oblique path's weights, normalised
};

}  // namespace

bool MsiObjectiveOptions::Oblique() const {
  return !headings_deg.empty() && !(headings_deg.size() == 1 && headings_deg[0] == 180.0);
}

bool MsiObjectiveOptions::IsValid(std::string* error) const {
  auto num = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return std::string(b);
  };
  std::string e;
  if (sea_weights.size() != seas.size())
    e = "sea_weights: " + std::to_string(sea_weights.size()) + " weights for " + std::to_string(seas.size()) + " seas";
  double sea_sum = 0.0;
  for (std::size_t i = 0; i < sea_weights.size() && e.empty(); ++i) {
    if (!(sea_weights[i] >= 0.0) || !std::isfinite(sea_weights[i]))
      e = "sea_weights[" + std::to_string(i) + "] = " + num(sea_weights[i]) + ": must be finite and >= 0";
    sea_sum += sea_weights[i];
  }
  if (e.empty() && !seas.empty() && !(sea_sum > 0.0)) e = "sea_weights: at least one weight must be > 0";
  if (e.empty() && !headings_deg.empty() && measure != Measure::kMsi && measure != Measure::kRmsAccel)
    e = "headings_deg: applies to the measures msi and rms_accel only";
  if (e.empty()) e = CheckHeadingList(headings_deg, "headings_deg");
  if (e.empty() && !heading_weights.empty()) {
    double sum = 0.0;
    if (heading_weights.size() != headings_deg.size())
      e = "heading_weights: " + std::to_string(heading_weights.size()) + " weights for " +
          std::to_string(headings_deg.size()) + " headings";
    for (std::size_t i = 0; i < heading_weights.size() && e.empty(); ++i) {
      if (!(heading_weights[i] >= 0.0) || !std::isfinite(heading_weights[i]))
        e = "heading_weights[" + std::to_string(i) + "] = " + num(heading_weights[i]) + ": must be finite and >= 0";
      sum += heading_weights[i];
    }
    if (e.empty() && !(sum > 0.0)) e = "heading_weights: at least one weight must be > 0";
  }
  if (e.empty()) return true;
  if (error) *error = e;
  return false;
}

std::unique_ptr<opt::Evaluator> MakeMsiEvaluator(DesignBasis basis, const std::vector<std::string>& variables,
                                                 MsiObjectiveOptions options) {
  return std::make_unique<MsiEvaluator>(std::move(basis), TrialFields(variables), std::move(options));
}

void CheckBaseDesign(const opt::Evaluator& evaluator) {
  const auto* m = dynamic_cast<const MsiEvaluator*>(&evaluator);
  if (m) BuildDesign(BasisSpec(m->basis(), "base design"));
}

}  // namespace hullopt::eval
