#include "seas/operability.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hullopt::sk {

bool ScatterDiagram::IsValid(std::string* error) const {
  std::ostringstream os;
  double sum = 0.0;
  if (cells.empty()) os << "the scatter diagram has no cells with a probability";
  for (size_t i = 0; i < cells.size() && os.str().empty(); ++i) {
    const ScatterCell& c = cells[i];
    if (!(c.probability >= 0.0) || !std::isfinite(c.probability)) {
      os << "cell " << i << " (Hs " << c.Hs_m << " m, " << (period_is_tp ? "Tp " : "Tz ") << c.period_s
         << " s): probability " << c.probability << " must be >= 0";
      break;
    }
    std::string e;
    if (!Sea(i).IsValid(&e)) {
      os << "cell " << i << " (Hs " << c.Hs_m << " m, " << (period_is_tp ? "Tp " : "Tz ") << c.period_s
         << " s): " << e;
      break;
    }
    sum += c.probability;
  }
  if (os.str().empty() && std::fabs(sum - 1.0) > kScatterProbabilitySumTol)
    os << "probabilities sum to " << sum << ", not 1 (tolerance " << kScatterProbabilitySumTol << ")";
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

SeaState ScatterDiagram::Sea(size_t i) const {
  const ScatterCell& c = cells[i];
  if (spectrum == SpectrumType::kBretschneider) {
    SeaState s = SeaState::BretschneiderTz(c.Hs_m, c.period_s);
    if (period_is_tp) {
      s.Tz_s = NAN;
      s.Tp_s = c.period_s;
    }
    return s;
  }
  return period_is_tp ? SeaState::JonswapTp(c.Hs_m, c.period_s, gamma) : SeaState::JonswapTz(c.Hs_m, c.period_s, gamma);
}

bool NordforskLimit(const std::string& activity, double* rms_g) {
  struct Entry {
    const char* name;
    double g;
  };
  static const Entry kTable[] = {{"light_manual_work", 0.20},
                                 {"heavy_manual_work", 0.15},
                                 {"intellectual_work", 0.10},
                                 {"transit_passengers", 0.05},
                                 {"cruise_liner", 0.02}};
  for (const auto& e : kTable)
    if (activity == e.name) {
      *rms_g = e.g;
      return true;
    }
  return false;
}

OperabilityResult EvaluateOperability(const RaoTable& rao, const HullExtent& hull, const ScatterDiagram& diagram,
                                      const std::vector<OperabilityCriterion>& criteria,
                                      const std::vector<PassengerPosition>& user_points,
                                      const EvaluationOptions& options) {
  std::string err;
  if (!diagram.IsValid(&err)) throw std::invalid_argument("scatter diagram: " + err);
  for (size_t j = 0; j < criteria.size(); ++j) {
    const OperabilityCriterion& c = criteria[j];
    if (!(c.limit > 0.0) || !std::isfinite(c.limit))
      throw std::invalid_argument("criterion '" + c.name + "': limit must be > 0");
    bool known = c.position == "mean" || c.position == "forward" || c.position == "lcg" || c.position == "transom";
    for (const auto& p : user_points) known = known || p.name == c.position;
    if (!known) throw std::invalid_argument("criterion '" + c.name + "': unknown position '" + c.position + "'");
  }
  std::vector<SeaState> seas;
  for (size_t i = 0; i < diagram.cells.size(); ++i) seas.push_back(diagram.Sea(i));
  const DesignEvaluation ev = EvaluateDesign(rao, hull, seas, user_points, options);
  OperabilityResult r;
  r.criterion_time_pct.assign(criteria.size(), 0.0);
  double psum = 0.0, msum = 0.0, all = 0.0;
  for (size_t i = 0; i < diagram.cells.size(); ++i) {
    CellResult cr;
    cr.cell = diagram.cells[i];
    cr.evaluation = ev.seas[i];
    const double p = cr.cell.probability;
    bool every = true;
    for (size_t j = 0; j < criteria.size(); ++j) {
      const OperabilityCriterion& c = criteria[j];
      const PositionResult* pos = &cr.evaluation.mean;
      for (const auto& q : cr.evaluation.positions)
        if (c.position != "mean" && q.position == c.position) pos = &q;
      const double v = c.is_msi ? pos->msi_pct : pos->rms_accel_g;
      const bool met = v <= c.limit;
      cr.criterion_met.push_back(met);
      if (met) r.criterion_time_pct[j] += p;
      every = every && met;
    }
    if (every) all += p;
    psum += p;
    msum += p * cr.evaluation.mean.msi_pct;
    r.cells.push_back(std::move(cr));
  }
  r.weighted_mean_msi_pct = msum / psum;
  for (double& t : r.criterion_time_pct) t *= 100.0 / psum;
  r.all_criteria_time_pct = 100.0 * all / psum;
  return r;
}

}  // namespace hullopt::sk
