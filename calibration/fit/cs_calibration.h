#pragma once
// Least-squares fit of the sectional damping coefficient Cs (D = ½ Cs ρ U v B, docs/theory.md, 'Sectional
// damping') to measured heave and pitch RAOs, with Ceres. The ship-motion model is abstract: a callable that
// returns the complex RAOs of one case at its measured points for a given Cs. With the fast strip solver this
// is cheap (the memory kernels do not depend on Cs; one 2×2 complex solve per frequency), so Ceres
// differentiates it numerically (central).
//
// Residuals, per measured point and quantity q ∈ {heave, pitch} with weight w_q > 0:
//   absolute:  r = w_q (|X_q computed| − |X_q measured|)               [RAO units × weight]
//   relative:  r = w_q (|X_q computed| − |X_q measured|) / |X_q measured|   [-]
//   phase (use_phases, when measured): r = w_q s |X_q measured| wrap(arg X_q computed − phase measured), with
//   s = 1 for absolute residuals and s = 1/|X_q measured| for relative ones: the phase error as an arc of the
//   measured RAO, in the same unit as the magnitude residual.
// Weights are inverse measurement standard deviations when they are known (then the reduced chi-square should
// be near 1); with w = 1 the residuals are plain RAO differences.
//
// Uncertainty convention (stated in every report): Ceres' covariance (JᵀJ)⁻¹ at the solution (with a robust
// loss, of the robustified Jacobian) is scaled by the residual variance σ̂² = 2·cost/(n − p), cost = ½ Σ ρ(r²)
// being Ceres' final cost, n the number of residuals and p the number of fitted parameters. The standard
// error is the square root of the diagonal. This is the "unknown scale" estimate (scipy curve_fit's
// absolute_sigma=False).
#include <complex>
#include <functional>
#include <string>
#include <vector>

#include "optimizer/rao_peak.h"
#include "optimizer/tank_rao_data.h"

namespace hullopt::calib {

/// Computed complex RAOs of one case at its measured points, in the order of opt::CalibrationCase::points.
struct RaoPrediction {
  std::vector<std::complex<double>> heave;  ///< X3/A [m/m]
  std::vector<std::complex<double>> pitch;  ///< X5/(kA) [-]
};

/// The ship-motion model seen by the fit: RAOs of case `case_index` for a damping coefficient Cs [-]. It is
/// called with Cs >= 0 only: below 0 (Ceres' central difference at the bound, or a line a + b·p below zero)
/// the fit extrapolates linearly from Cs = 0 and Cs = 1e-6. It may throw: during the fit that rejects the
/// Ceres step (reported in the warnings); at the start or final value CalibrateCs throws std::domain_error.
using CsRaoModel = std::function<RaoPrediction(double Cs, int case_index)>;

enum class CsFitMode {
  kSingle,             ///< one Cs for every case
  kPerCase,            ///< one Cs per case (hull × speed); `per_speed` in the config
  kLinearInParameter,  ///< Cs = a + b·p with p = opt::CalibrationCase::hull_parameter, across several hulls
};
enum class CsResidualScale { kAbsolute, kRelative };
enum class CsRobustLoss { kNone, kHuber, kCauchy };

struct CsCalibrationOptions {
  CsFitMode mode = CsFitMode::kSingle;
  CsResidualScale residual_scale = CsResidualScale::kAbsolute;
  double heave_weight = 1.0;  ///< w_heave ≥ 0 [1/(m/m)], 0 leaves heave out
  double pitch_weight = 1.0;  ///< w_pitch ≥ 0 [-], 0 leaves pitch out
  bool use_phases = false;    ///< add phase residuals where the data has phases
  CsRobustLoss loss = CsRobustLoss::kNone;
  double loss_scale = 1.0;   ///< robust loss scale (residual size where it starts to down-weight), > 0
  double Cs_initial = 0.05;  ///< [-] start value (also the "before" of the before/after comparison), ≥ 0
  double slope_initial =
      0.0;  ///< [-/unit p] start value of b in mode kLinearInParameter (a starts at Cs_initial)
  int max_iterations = 100;            ///< Ceres trust-region iterations, ≥ 1
  double function_tolerance = 1e-12;   ///< Ceres relative cost-change tolerance, > 0
  double parameter_tolerance = 1e-12;  ///< Ceres relative step tolerance, > 0

  /// False with a one-line reason (field, value, rule) when an option is out of range.
  bool IsValid(std::string* error) const;
};

/// Checks that the data can determine the parameters: every case has points, relative residuals have non-zero
/// measured RAOs, use_phases finds at least one phase, n residuals > p parameters (per case in mode
/// kPerCase), and mode kLinearInParameter has at least two distinct hull parameters. False with a reason
/// naming case and counts.
bool CheckCalibrationData(const std::vector<opt::CalibrationCase>& cases, const CsCalibrationOptions& options,
                          std::string* error);

/// One residual of the fit.
struct CsPointResidual {
  int case_index = 0;
  int point_index = 0;           ///< index into opt::CalibrationCase::points
  std::string quantity;          ///< "heave", "pitch", "heave_phase" or "pitch_phase"
  std::string source;            ///< "file:line" of the measured row
  double measured = 0.0;         ///< |X| measured, or the phase [deg]
  double computed_before = 0.0;  ///< at Cs_initial: |X| or phase [deg]
  double computed_after = 0.0;   ///< at the fitted Cs
  double residual_before = 0.0;  ///< weighted residual r at Cs_initial (see the file comment for its unit)
  double residual_after = 0.0;   ///< weighted residual r at the fitted Cs
};

/// Peak of the measured and computed magnitude curves of one case and quantity (interpolated, see
/// rao_peak.h).
struct CsPeakChange {
  int case_index = 0;
  std::string quantity;  ///< "heave" or "pitch"
  std::string abscissa;  ///< "omega_e_rad_s" or "lambda_over_L": the x of the peaks
  opt::RaoPeak measured, before, after;
  double RelativeErrorBefore() const { return (before.value - measured.value) / measured.value; }
  double RelativeErrorAfter() const { return (after.value - measured.value) / measured.value; }
};

/// Fewer residuals than this per fitted parameter gives a warning: with n close to p the residual variance,
/// hence every standard error, rests on a handful of points.
constexpr int kMinPointsPerParameter = 3;

struct CsCalibrationResult {
  CsFitMode mode = CsFitMode::kSingle;
  std::vector<std::string> parameter_names;     ///< "Cs"; "Cs[<case label>]" per case; or "a", "b"
  std::vector<double> parameters;               ///< fitted values
  std::vector<double> parameter_std_errors;     ///< 1σ standard errors (convention in the file comment)
  std::vector<std::vector<double>> covariance;  ///< scaled covariance of the parameters (p × p)
  std::vector<double> case_Cs;                  ///< Cs applied to each case after the fit
  std::vector<double> case_Cs_std_error;        ///< its standard error (propagated through a + b·p)
  int num_residuals = 0;                        ///< n
  int num_parameters = 0;                       ///< p
  double initial_cost = 0.0;                    ///< Ceres cost ½ Σ ρ(r²) at the start
  double final_cost = 0.0;                      ///< Ceres cost at the solution
  double residual_variance = 0.0;               ///< σ̂² = 2·final_cost/(n − p)
  double rms_residual_before = 0.0;             ///< sqrt(Σ r²/n) at Cs_initial (no robust loss)
  double rms_residual = 0.0;                    ///< sqrt(Σ r²/n) at the solution (no robust loss)
  double reduced_chi_square = 0.0;              ///< Σ r²/(n − p) at the solution (no robust loss)
  std::vector<CsPointResidual> residuals;
  std::vector<CsPeakChange> peaks;
  std::vector<RaoPrediction> predictions_before;  ///< per case, at Cs_initial (for plots)
  std::vector<RaoPrediction> predictions_after;   ///< per case, at the fitted Cs
  bool converged = false;                         ///< Ceres reported convergence
  bool covariance_ok = false;         ///< Ceres could compute the covariance (else std errors are 0)
  std::vector<std::string> warnings;  ///< e.g. a parameter at its bound, a negative Cs from a + b·p
  std::string ceres_brief;            ///< ceres::Solver::Summary::BriefReport()
  std::string ceres_full;             ///< ceres::Solver::Summary::FullReport()
  double fit_seconds = 0.0;           ///< wall time of the fit, model evaluations included [s]
  int model_evaluations = 0;          ///< calls of the model

  /// One paragraph: mode, fitted values ± 1σ, n, p, rms before → after, reduced chi-square, convergence.
  std::string BriefReport() const;
  /// The brief report, the uncertainty convention, peaks, per-point residuals, warnings and Ceres' full
  /// report.
  std::string FullReport() const;
};

/// Fits Cs. Throws std::invalid_argument when options are invalid or CheckCalibrationData fails, and
/// std::domain_error when the model returns the wrong number of points or a non-finite RAO at the start
/// value.
CsCalibrationResult CalibrateCs(const CsRaoModel& model, const std::vector<opt::CalibrationCase>& cases,
                                const CsCalibrationOptions& options);

/// Names used in configs and reports: "single", "per_speed", "linear_in_parameter"; "absolute", "relative";
/// "none", "huber", "cauchy".
std::string ToString(CsFitMode mode);
std::string ToString(CsResidualScale scale);
std::string ToString(CsRobustLoss loss);

}  // namespace hullopt::calib
