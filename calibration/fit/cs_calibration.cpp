#include "calibration/fit/cs_calibration.h"

#include <ceres/ceres.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>

namespace hullopt::calib {
namespace {

constexpr double kPi = 3.14159265358979323846;
// A fitted Cs below this is "at the bound 0" for the warning (Cs of real hulls is 0.0–0.135; 1e-9 is far
// below any meaningful value and far above Ceres' projection round-off).
constexpr double kAtBound = 1e-9;

enum Kind { kHeave = 0, kPitch = 1, kHeavePhase = 2, kPitchPhase = 3 };
const char* KindName(int k) {
  static const char* names[] = {"heave", "pitch", "heave_phase", "pitch_phase"};
  return names[k];
}

/// Which residual each slot of a case's residual vector holds.
struct Slot {
  int point;
  Kind kind;
};

std::vector<Slot> Layout(const opt::CalibrationCase& c, const CsCalibrationOptions& o) {
  std::vector<Slot> slots;
  for (int i = 0; i < static_cast<int>(c.points.size()); ++i) {
    const opt::TankRaoPoint& p = c.points[i];
    if (o.heave_weight > 0) slots.push_back({i, kHeave});
    if (o.pitch_weight > 0) slots.push_back({i, kPitch});
    if (o.use_phases && o.heave_weight > 0 && p.has_heave_phase) slots.push_back({i, kHeavePhase});
    if (o.use_phases && o.pitch_weight > 0 && p.has_pitch_phase) slots.push_back({i, kPitchPhase});
  }
  return slots;
}

double WrapPi(double a) { return std::remainder(a, 2.0 * kPi); }

double Measured(const opt::TankRaoPoint& p, Kind k) {
  switch (k) {
    case kHeave:
      return p.heave_amp;
    case kPitch:
      return p.pitch_amp;
    case kHeavePhase:
      return p.heave_phase_deg;
    default:
      return p.pitch_phase_deg;
  }
}

/// Computed magnitude, or phase [deg], of a slot.
double Computed(const RaoPrediction& r, const Slot& s) {
  const std::complex<double> x =
      (s.kind == kHeave || s.kind == kHeavePhase) ? r.heave[s.point] : r.pitch[s.point];
  if (s.kind == kHeave || s.kind == kPitch) return std::abs(x);
  return std::arg(x) * 180.0 / kPi;
}

double SlotResidual(const opt::CalibrationCase& c, const RaoPrediction& r, const Slot& s,
                    const CsCalibrationOptions& o) {
  const opt::TankRaoPoint& p = c.points[s.point];
  const bool heave = (s.kind == kHeave || s.kind == kHeavePhase);
  const double w = heave ? o.heave_weight : o.pitch_weight;
  const double meas_amp = heave ? p.heave_amp : p.pitch_amp;
  const double scale = o.residual_scale == CsResidualScale::kRelative ? 1.0 / meas_amp : 1.0;
  if (s.kind == kHeave || s.kind == kPitch) return w * scale * (Computed(r, s) - meas_amp);
  const double dphi = WrapPi((Computed(r, s) - Measured(p, s.kind)) * kPi / 180.0);
  return w * scale * meas_amp * dphi;
}

bool PredictionOk(const RaoPrediction& r, std::size_t n) {
  if (r.heave.size() != n || r.pitch.size() != n) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(r.heave[i].real()) || !std::isfinite(r.heave[i].imag())) return false;
    if (!std::isfinite(r.pitch[i].real()) || !std::isfinite(r.pitch[i].imag())) return false;
  }
  return true;
}

double CaseCs(const double* x, int block_size, double p) { return block_size == 1 ? x[0] : x[0] + x[1] * p; }

/// Below Cs = 0 the model is not evaluated (a real solver refuses a negative damping coefficient, and Ceres'
/// central difference at the bound asks for Cs = −h): the prediction is extrapolated linearly from Cs = 0 and
/// Cs = kExtrapolationStep. 1e-6 is far below any meaningful Cs (0.0–0.135) and far above round-off.
constexpr double kExtrapolationStep = 1e-6;

RaoPrediction Extrapolate(const RaoPrediction& p0, const RaoPrediction& p1, double Cs) {
  RaoPrediction r = p0;
  const double t = Cs / kExtrapolationStep;
  for (std::size_t i = 0; i < r.heave.size() && i < p1.heave.size(); ++i)
    r.heave[i] += t * (p1.heave[i] - p0.heave[i]);
  for (std::size_t i = 0; i < r.pitch.size() && i < p1.pitch.size(); ++i)
    r.pitch[i] += t * (p1.pitch[i] - p0.pitch[i]);
  return r;
}

/// The model at any Cs (extrapolated below 0). Model exceptions propagate.
RaoPrediction EvaluateModel(const CsRaoModel& model, double Cs, int case_index,
                            std::atomic<int>* evaluations) {
  if (Cs >= 0) {
    ++*evaluations;
    return model(Cs, case_index);
  }
  *evaluations += 2;
  return Extrapolate(model(0.0, case_index), model(kExtrapolationStep, case_index), Cs);
}

/// The last few predictions of one case. Every residual is its own Ceres residual block (a robust loss acts
/// on the squared norm of a whole block, so it must see one residual at a time), and the blocks of a case are
/// evaluated one after another at the same Cs, Cs + h and Cs − h: the cache turns n model calls into one.
/// A model that throws or returns an unusable prediction makes the evaluation fail (Ceres rejects the step).
/// Used from Ceres' single evaluation thread; the returned pointer is valid until the next Get.
class PredictionCache {
 public:
  PredictionCache(const CsRaoModel* model, int case_index, std::size_t points, std::atomic<int>* evaluations)
      : model_(model), case_index_(case_index), points_(points), evaluations_(evaluations) {}
  /// Null when the model's answer is unusable (exception, wrong size or non-finite).
  const RaoPrediction* Get(double Cs) {
    if (Cs >= 0) return Raw(Cs);
    const RaoPrediction* p0 = Raw(0.0);
    if (!p0) return nullptr;
    const RaoPrediction zero = *p0;  // Raw may reuse p0's slot
    const RaoPrediction* p1 = Raw(kExtrapolationStep);
    if (!p1) return nullptr;
    extrapolated_ = Extrapolate(zero, *p1, Cs);
    return &extrapolated_;
  }
  const std::string& last_error() const { return last_error_; }

 private:
  const RaoPrediction* Raw(double Cs) {
    for (const auto& e : entries_)
      if (e.valid && e.Cs == Cs) return e.ok ? &e.prediction : nullptr;
    Entry& e = entries_[next_];
    next_ = (next_ + 1) % entries_.size();
    e.Cs = Cs;
    e.valid = true;
    ++*evaluations_;
    try {
      e.prediction = (*model_)(Cs, case_index_);
      e.ok = PredictionOk(e.prediction, points_);
      if (!e.ok) last_error_ = "wrong number of points or a non-finite RAO at Cs = " + std::to_string(Cs);
    } catch (const std::exception& ex) {
      e.ok = false;
      last_error_ = ex.what();
    }
    return e.ok ? &e.prediction : nullptr;
  }

  struct Entry {
    bool valid = false, ok = false;
    double Cs = 0.0;
    RaoPrediction prediction;
  };
  const CsRaoModel* model_;
  int case_index_;
  std::size_t points_;
  std::atomic<int>* evaluations_;
  std::array<Entry, 8> entries_;  // Cs and Cs ± h per parameter (5 values for a + b·p), the trial step
  std::size_t next_ = 0;
  RaoPrediction extrapolated_;
  std::string last_error_;
};

/// One residual; parameter block of size N (1: Cs, 2: a and b of Cs = a + b·p).
template <int N>
struct SlotCost {
  PredictionCache* cache;
  const opt::CalibrationCase* c;
  Slot slot;
  CsCalibrationOptions options;

  bool operator()(const double* x, double* residual) const {
    const RaoPrediction* r = cache->Get(CaseCs(x, N, c->hull_parameter));
    if (!r) return false;  // Ceres rejects the step
    residual[0] = SlotResidual(*c, *r, slot, options);
    return true;
  }
};

std::string Fmt(double v, const char* f = "%.6g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace

std::string ToString(CsFitMode mode) {
  switch (mode) {
    case CsFitMode::kSingle:
      return "single";
    case CsFitMode::kPerCase:
      return "per_speed";
    default:
      return "linear_in_parameter";
  }
}
std::string ToString(CsResidualScale scale) {
  return scale == CsResidualScale::kAbsolute ? "absolute" : "relative";
}
std::string ToString(CsRobustLoss loss) {
  switch (loss) {
    case CsRobustLoss::kNone:
      return "none";
    case CsRobustLoss::kHuber:
      return "huber";
    default:
      return "cauchy";
  }
}

bool CsCalibrationOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& msg) {
    if (error) *error = msg;
    return false;
  };
  if (!(std::isfinite(heave_weight) && heave_weight >= 0))
    return fail("heave_weight = " + Fmt(heave_weight) + ": must be a finite number >= 0");
  if (!(std::isfinite(pitch_weight) && pitch_weight >= 0))
    return fail("pitch_weight = " + Fmt(pitch_weight) + ": must be a finite number >= 0");
  if (heave_weight == 0 && pitch_weight == 0)
    return fail("heave_weight = pitch_weight = 0: at least one quantity must be fitted");
  if (loss != CsRobustLoss::kNone && !(std::isfinite(loss_scale) && loss_scale > 0))
    return fail("loss_scale = " + Fmt(loss_scale) + ": must be a finite number > 0 for loss " +
                ToString(loss));
  if (!(std::isfinite(Cs_initial) && Cs_initial >= 0))
    return fail("Cs_initial = " + Fmt(Cs_initial) +
                ": must be a finite number >= 0 (Cs is a damping coefficient)");
  if (!std::isfinite(slope_initial))
    return fail("slope_initial = " + Fmt(slope_initial) + ": must be finite");
  if (max_iterations < 1)
    return fail("max_iterations = " + std::to_string(max_iterations) + ": must be >= 1");
  if (!(function_tolerance > 0) || !(parameter_tolerance > 0))
    return fail("function_tolerance and parameter_tolerance must be > 0");
  return true;
}

bool CheckCalibrationData(const std::vector<opt::CalibrationCase>& cases, const CsCalibrationOptions& o,
                          std::string* error) {
  auto fail = [&](const std::string& msg) {
    if (error) *error = msg;
    return false;
  };
  if (cases.empty()) return fail("no calibration cases (no measured data)");
  int n = 0;
  bool any_phase = false;
  std::set<double> params;
  for (const opt::CalibrationCase& c : cases) {
    if (c.points.empty()) return fail("case '" + c.label + "' has no measured points");
    for (const opt::TankRaoPoint& p : c.points) {
      any_phase = any_phase || p.has_heave_phase || p.has_pitch_phase;
      if (o.residual_scale == CsResidualScale::kRelative) {
        if (o.heave_weight > 0 && !(p.heave_amp > 0))
          return fail(p.source + ": heave_rao = " + Fmt(p.heave_amp) +
                      ": relative residuals divide by the measured RAO, which must be > 0");
        if (o.pitch_weight > 0 && !(p.pitch_amp > 0))
          return fail(p.source + ": pitch_rao = " + Fmt(p.pitch_amp) +
                      ": relative residuals divide by the measured RAO, which must be > 0");
      }
    }
    const int nc = static_cast<int>(Layout(c, o).size());
    if (o.mode == CsFitMode::kPerCase && nc <= 1) {
      return fail(
          "case '" + c.label + "' gives " + std::to_string(nc) + " residual(s) (" +
          std::to_string(c.points.size()) +
          " point(s)) for 1 fitted Cs: mode per_speed needs more residuals than parameters (n > p) in "
          "every case to estimate Cs and its standard error");
    }
    n += nc;
    params.insert(c.hull_parameter);
  }
  if (o.use_phases && !any_phase)
    return fail("use_phases is true but no data row has heave_phase_deg or pitch_phase_deg");
  const int p = o.mode == CsFitMode::kSingle    ? 1
                : o.mode == CsFitMode::kPerCase ? static_cast<int>(cases.size())
                                                : 2;
  if (n <= p) {
    return fail(
        "the data gives " + std::to_string(n) + " residual(s) for " + std::to_string(p) +
        " fitted parameter(s) (mode " + ToString(o.mode) +
        "): the fit needs more residuals than parameters (n > p) to estimate Cs and its standard error");
  }
  if (o.mode == CsFitMode::kLinearInParameter && params.size() < 2) {
    return fail("mode linear_in_parameter fits Cs = a + b*p but all " + std::to_string(cases.size()) +
                " case(s) have the same hull parameter p = " + Fmt(*params.begin()) +
                ": at least two hulls with different p are needed");
  }
  return true;
}

CsCalibrationResult CalibrateCs(const CsRaoModel& model, const std::vector<opt::CalibrationCase>& cases,
                                const CsCalibrationOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  std::string error;
  if (!o.IsValid(&error)) throw std::invalid_argument("Cs calibration options: " + error);
  if (!CheckCalibrationData(cases, o, &error)) throw std::invalid_argument("Cs calibration data: " + error);
  if (!model) throw std::invalid_argument("Cs calibration: the RAO model is empty");

  const int num_cases = static_cast<int>(cases.size());
  std::atomic<int> evaluations{0};
  CsCalibrationResult res;
  res.mode = o.mode;

  // Parameters: one block for kSingle, one per case for kPerCase, one block of two for kLinearInParameter.
  const int block_size = o.mode == CsFitMode::kLinearInParameter ? 2 : 1;
  const int num_blocks = o.mode == CsFitMode::kPerCase ? num_cases : 1;
  std::vector<std::vector<double>> blocks(num_blocks, std::vector<double>(block_size));
  for (auto& b : blocks) {
    b[0] = o.Cs_initial;
    if (block_size == 2) b[1] = o.slope_initial;
  }
  auto block_of = [&](int c) -> double* { return blocks[o.mode == CsFitMode::kPerCase ? c : 0].data(); };

  // Start values: the prediction must be usable (otherwise Ceres would only report a failed first
  // evaluation).
  std::vector<std::vector<Slot>> layouts(num_cases);
  std::vector<RaoPrediction> before(num_cases);
  for (int c = 0; c < num_cases; ++c) {
    layouts[c] = Layout(cases[c], o);
    const double Cs = CaseCs(block_of(c), block_size, cases[c].hull_parameter);
    try {
      before[c] = EvaluateModel(model, Cs, c, &evaluations);
    } catch (const std::exception& e) {
      throw std::domain_error("Cs calibration: the RAO model failed for case '" + cases[c].label +
                              "' at the start value Cs = " + Fmt(Cs) + ": " + e.what());
    }
    if (!PredictionOk(before[c], cases[c].points.size())) {
      throw std::domain_error(
          "Cs calibration: the RAO model returned " + std::to_string(before[c].heave.size()) + " heave and " +
          std::to_string(before[c].pitch.size()) + " pitch values (or a non-finite one) for case '" +
          cases[c].label + "' with " + std::to_string(cases[c].points.size()) + " points at Cs = " + Fmt(Cs));
    }
  }

  ceres::Problem problem;
  std::vector<std::unique_ptr<PredictionCache>> caches;
  for (int c = 0; c < num_cases; ++c) {
    caches.push_back(std::make_unique<PredictionCache>(&model, c, cases[c].points.size(), &evaluations));
    for (const Slot& slot : layouts[c]) {
      ceres::LossFunction* loss = nullptr;
      if (o.loss == CsRobustLoss::kHuber) loss = new ceres::HuberLoss(o.loss_scale);
      if (o.loss == CsRobustLoss::kCauchy) loss = new ceres::CauchyLoss(o.loss_scale);
      ceres::CostFunction* cost = nullptr;
      if (block_size == 1) {
        cost = new ceres::NumericDiffCostFunction<SlotCost<1>, ceres::CENTRAL, 1, 1>(
            new SlotCost<1>{caches.back().get(), &cases[c], slot, o});
      } else {
        cost = new ceres::NumericDiffCostFunction<SlotCost<2>, ceres::CENTRAL, 1, 2>(
            new SlotCost<2>{caches.back().get(), &cases[c], slot, o});
      }
      problem.AddResidualBlock(cost, loss, block_of(c));
      ++res.num_residuals;
    }
  }
  // Cs >= 0: a damping coefficient. For Cs = a + b·p the bound is on the line, not on a block; checked
  // afterwards.
  if (block_size == 1)
    for (auto& b : blocks) problem.SetParameterLowerBound(b.data(), 0, 0.0);

  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = o.max_iterations;
  so.function_tolerance = o.function_tolerance;
  so.parameter_tolerance = o.parameter_tolerance;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  res.converged = summary.termination_type == ceres::CONVERGENCE;
  res.initial_cost = summary.initial_cost;
  res.final_cost = summary.final_cost;
  res.ceres_brief = summary.BriefReport();
  res.ceres_full = summary.FullReport();
  std::string model_errors;
  for (int c = 0; c < num_cases; ++c) {
    if (caches[c]->last_error().empty()) continue;
    res.warnings.push_back("the RAO model failed during the fit for case '" + cases[c].label +
                           "' (Ceres rejected that step): " + caches[c]->last_error());
    model_errors += "; case '" + cases[c].label + "': " + caches[c]->last_error();
  }
  if (!summary.IsSolutionUsable()) {
    throw std::domain_error("Cs calibration: Ceres found no usable solution: " + summary.message +
                            model_errors);
  }
  if (!std::isfinite(summary.initial_cost) || !std::isfinite(summary.final_cost))
    throw std::domain_error("Cs calibration: the residuals overflow (cost " + Fmt(summary.final_cost) +
                            "): a measured or computed RAO is too large to fit");
  if (!res.converged) res.warnings.push_back("Ceres did not report convergence: " + summary.message);

  res.num_parameters = num_blocks * block_size;
  const int n = res.num_residuals, p = res.num_parameters;
  res.residual_variance = 2.0 * res.final_cost / (n - p);

  // Parameters and their covariance: Ceres' (JᵀJ)⁻¹ scaled by σ̂².
  for (int b = 0; b < num_blocks; ++b) {
    for (int k = 0; k < block_size; ++k) res.parameters.push_back(blocks[b][k]);
  }
  if (o.mode == CsFitMode::kSingle) res.parameter_names = {"Cs"};
  if (o.mode == CsFitMode::kPerCase)
    for (const auto& c : cases) res.parameter_names.push_back("Cs[" + c.label + "]");
  if (o.mode == CsFitMode::kLinearInParameter) res.parameter_names = {"a", "b"};
  res.covariance.assign(p, std::vector<double>(p, 0.0));
  {
    ceres::Covariance::Options co;
    co.algorithm_type =
        ceres::DENSE_SVD;  // tiny problems; SVD also reports rank deficiency instead of failing
    ceres::Covariance cov(co);
    std::vector<std::pair<const double*, const double*>> pairs;
    for (auto& b : blocks) pairs.emplace_back(b.data(), b.data());  // blocks are independent (per case)
    res.covariance_ok = cov.Compute(pairs, &problem);
    if (res.covariance_ok) {
      for (int b = 0; b < num_blocks; ++b) {
        std::vector<double> m(block_size * block_size);
        cov.GetCovarianceBlock(blocks[b].data(), blocks[b].data(), m.data());
        for (int i = 0; i < block_size; ++i)
          for (int j = 0; j < block_size; ++j)
            res.covariance[b * block_size + i][b * block_size + j] =
                m[i * block_size + j] * res.residual_variance;
      }
    } else {
      res.warnings.push_back(
          "Ceres could not compute the covariance (Jacobian rank deficient: the data do not "
          "depend on Cs?); standard errors are reported as 0");
    }
  }
  for (int i = 0; i < p; ++i)
    res.parameter_std_errors.push_back(std::sqrt(std::max(0.0, res.covariance[i][i])));
  // A fit whose uncertainty is unknown has not converged in any useful sense, whatever Ceres says.
  for (int i = 0; i < p; ++i) {
    if (std::isfinite(res.parameters[i]) && std::isfinite(res.parameter_std_errors[i])) continue;
    res.converged = false;
    res.warnings.push_back("parameter " + res.parameter_names[i] + " = " + Fmt(res.parameters[i]) +
                           " has a non-finite standard error (" + Fmt(res.parameter_std_errors[i]) +
                           "): the fit is not converged; check the data for outliers");
  }

  // Per-case Cs, before/after residuals and peaks.
  double ss_before = 0, ss_after = 0;
  for (int c = 0; c < num_cases; ++c) {
    const opt::CalibrationCase& cc = cases[c];
    const double* x = block_of(c);
    const double Cs = CaseCs(x, block_size, cc.hull_parameter);
    res.case_Cs.push_back(Cs);
    const int b0 = (o.mode == CsFitMode::kPerCase ? c : 0) * block_size;
    double var = res.covariance[b0][b0];
    if (block_size == 2) {
      const double q = cc.hull_parameter;
      var += 2 * q * res.covariance[b0][b0 + 1] + q * q * res.covariance[b0 + 1][b0 + 1];
    }
    res.case_Cs_std_error.push_back(std::sqrt(std::max(0.0, var)));
    if (!std::isfinite(res.case_Cs_std_error.back()) && res.converged) {
      res.converged = false;
      res.warnings.push_back("Cs of case '" + cc.label + "' has a non-finite standard error: the fit is not converged");
    }
    if (block_size == 1 && Cs < kAtBound) {
      res.warnings.push_back("Cs of case '" + cc.label +
                             "' is at its lower bound 0: the standard error ignores the bound");
    }
    if (block_size == 2 && Cs < 0) {
      res.warnings.push_back("Cs = a + b*p is negative (" + Fmt(Cs) + ") for case '" + cc.label + "' (p = " +
                             Fmt(cc.hull_parameter) + "): the line is not bounded, check the data");
    }
    RaoPrediction after;
    try {
      after = EvaluateModel(model, Cs, c, &evaluations);
    } catch (const std::exception& e) {
      throw std::domain_error("Cs calibration: the RAO model failed at the fitted Cs = " + Fmt(Cs) + ": " +
                              e.what());
    }
    if (!PredictionOk(after, cc.points.size()))
      throw std::domain_error("Cs calibration: the RAO model failed at the fitted Cs = " + Fmt(Cs));
    res.predictions_before.push_back(before[c]);
    res.predictions_after.push_back(after);
    for (const Slot& s : layouts[c]) {
      CsPointResidual r;
      r.case_index = c;
      r.point_index = s.point;
      r.quantity = KindName(s.kind);
      r.source = cc.points[s.point].source;
      r.measured = Measured(cc.points[s.point], s.kind);
      r.computed_before = Computed(before[c], s);
      r.computed_after = Computed(after, s);
      r.residual_before = SlotResidual(cc, before[c], s, o);
      r.residual_after = SlotResidual(cc, after, s, o);
      ss_before += r.residual_before * r.residual_before;
      ss_after += r.residual_after * r.residual_after;
      res.residuals.push_back(r);
    }
    // Peaks on the abscissa every point of the case has (encounter frequency preferred).
    bool all_w = true, all_l = true;
    for (const auto& pt : cc.points) {
      all_w = all_w && pt.has_omega_e;
      all_l = all_l && pt.has_lambda_over_L;
    }
    if (!all_w && !all_l) {
      res.warnings.push_back("case '" + cc.label +
                             "' mixes rows with only omega_e and only lambda_over_L: no peaks");
      continue;
    }
    for (int q = 0; q < 2; ++q) {
      std::vector<double> xs, ym, yb, ya;
      for (std::size_t i = 0; i < cc.points.size(); ++i) {
        const auto& pt = cc.points[i];
        xs.push_back(all_w ? pt.omega_e_rad_s : pt.lambda_over_L);
        ym.push_back(q == 0 ? pt.heave_amp : pt.pitch_amp);
        yb.push_back(std::abs(q == 0 ? before[c].heave[i] : before[c].pitch[i]));
        ya.push_back(std::abs(q == 0 ? after.heave[i] : after.pitch[i]));
      }
      CsPeakChange pk;
      pk.case_index = c;
      pk.quantity = q == 0 ? "heave" : "pitch";
      pk.abscissa = all_w ? "omega_e_rad_s" : "lambda_over_L";
      pk.measured = opt::InterpolatedPeak(xs, ym);
      pk.before = opt::InterpolatedPeak(xs, yb);
      pk.after = opt::InterpolatedPeak(xs, ya);
      if (!(pk.measured.value > 0)) {  // no relative peak error against an all-zero measurement
        res.warnings.push_back("case '" + cc.label + "': every measured " + pk.quantity +
                               " RAO is 0, no peak comparison");
        continue;
      }
      res.peaks.push_back(pk);
    }
  }
  res.rms_residual_before = std::sqrt(ss_before / n);
  res.rms_residual = std::sqrt(ss_after / n);
  res.reduced_chi_square = ss_after / (n - p);
  res.model_evaluations = evaluations.load();
  res.fit_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Honesty of the fit: a "converged" fit says nothing if the data barely determine the parameters.
  if (n < kMinPointsPerParameter * p)
    res.warnings.push_back("only " + std::to_string(n) + " data point(s) for " + std::to_string(p) +
                           " fitted parameter(s) (fewer than " + std::to_string(kMinPointsPerParameter) +
                           " per parameter): the fit and its standard errors are not meaningful");
  for (int i = 0; i < p; ++i)
    if (res.parameter_std_errors[i] > std::fabs(res.parameters[i]))
      res.warnings.push_back("the standard error of " + res.parameter_names[i] + " (" +
                             Fmt(res.parameter_std_errors[i]) + ") is larger than its value (" +
                             Fmt(res.parameters[i]) + "): the data do not determine it");
  return res;
}

std::string CsCalibrationResult::BriefReport() const {
  std::ostringstream s;
  s << "Cs calibration (" << ToString(mode) << "):";
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    s << " " << parameter_names[i] << " = " << Fmt(parameters[i], "%.5g") << " ± "
      << Fmt(parameter_std_errors[i], "%.2g") << (i + 1 < parameters.size() ? "," : "");
  }
  s << " (1σ); n = " << num_residuals << ", p = " << num_parameters << ", rms residual "
    << Fmt(rms_residual_before, "%.4g") << " -> " << Fmt(rms_residual, "%.4g") << ", reduced chi-square "
    << Fmt(reduced_chi_square, "%.4g") << ", " << (converged ? "converged" : "NOT converged") << ", "
    << model_evaluations << " model evaluations, " << Fmt(fit_seconds, "%.3g") << " s";
  if (!warnings.empty()) s << "; " << warnings.size() << " warning(s)";
  return s.str();
}

std::string CsCalibrationResult::FullReport() const {
  std::ostringstream s;
  s << BriefReport() << "\n\n";
  s << "Uncertainty: standard error = sqrt(diag(C)), C = (J^T J)^-1 * s2 (Ceres covariance at the solution, "
       "robustified Jacobian with a loss), s2 = 2*cost/(n - p) = "
    << Fmt(residual_variance) << " (cost = " << Fmt(final_cost) << ", n = " << num_residuals
    << ", p = " << num_parameters << ")" << (covariance_ok ? "" : " -- covariance FAILED") << "\n";
  s << "\nParameters:\n";
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    s << "  " << parameter_names[i] << " = " << Fmt(parameters[i], "%.6g") << " ± "
      << Fmt(parameter_std_errors[i], "%.3g") << "\n";
  }
  if (mode == CsFitMode::kLinearInParameter && covariance.size() == 2) {
    s << "  cov(a, b) = " << Fmt(covariance[0][1], "%.3g") << "\n";
  }
  s << "\nCs per case:\n";
  for (std::size_t c = 0; c < case_Cs.size(); ++c) {
    s << "  case " << c << ": Cs = " << Fmt(case_Cs[c], "%.6g") << " ± " << Fmt(case_Cs_std_error[c], "%.3g")
      << "\n";
  }
  s << "\nPeaks (interpolated; relative error of the computed peak against the measured one):\n";
  for (const auto& pk : peaks) {
    s << "  case " << pk.case_index << " " << pk.quantity << ": measured " << Fmt(pk.measured.value, "%.4g")
      << " at " << pk.abscissa << " " << Fmt(pk.measured.x, "%.4g")
      << (pk.measured.at_edge ? " (at data edge)" : "") << "; before " << Fmt(pk.before.value, "%.4g") << " ("
      << Fmt(100 * pk.RelativeErrorBefore(), "%+.1f") << "%), after " << Fmt(pk.after.value, "%.4g") << " ("
      << Fmt(100 * pk.RelativeErrorAfter(), "%+.1f") << "%)\n";
  }
  s << "\nResiduals (weighted; computed before at the initial Cs, after at the fitted Cs):\n";
  s << "  source  quantity  measured  computed_before  computed_after  residual_before  residual_after\n";
  for (const auto& r : residuals) {
    s << "  " << r.source << "  " << r.quantity << "  " << Fmt(r.measured, "%.4g") << "  "
      << Fmt(r.computed_before, "%.4g") << "  " << Fmt(r.computed_after, "%.4g") << "  "
      << Fmt(r.residual_before, "%+.4g") << "  " << Fmt(r.residual_after, "%+.4g") << "\n";
  }
  if (!warnings.empty()) {
    s << "\nWarnings:\n";
    for (const auto& w : warnings) s << "  " << w << "\n";
  }
  s << "\n" << ceres_full;
  return s.str();
}

}  // namespace hullopt::calib
