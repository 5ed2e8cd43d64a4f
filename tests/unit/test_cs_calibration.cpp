// Ceres Cs fit against closed forms: with an RAO magnitude linear in Cs, least squares is linear regression,
// so the fitted values, the scaled covariance and the reduced chi-square have textbook formulas (solved here
// with Eigen, independently of Ceres). Robust loss against a bisection solution of the Huber M-estimator
// equation.
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>

#include "calibration/fit/cs_calibration.h"
#include "calibration/fit/synthetic_oscillator_rao.h"

using namespace hullopt::opt;
using namespace hullopt::calib;

namespace {
// Ceres stops on relative cost change 1e-10 / step 1e-10 and differentiates numerically (central, relative
// step 1e-6, error ~1e-12 relative for a linear model): 1e-7 relative on the fitted values is well inside
// that.
constexpr double kFitTol = 1e-7;
// Standard errors come from Ceres' SVD of J and the numeric Jacobian; 1e-6 relative.
constexpr double kStdErrTol = 1e-6;
// The Huber optimum of the outlier test sits where one residual crosses the loss scale δ (a kink in the
// gradient), which Levenberg–Marquardt approaches only linearly: 1e-5 relative (5e-7 absolute on Cs ≈ 0.045).
constexpr double kRobustFitTol = 1e-5;

// Case c, point i: |heave| = a + b·Cs, |pitch| = a' + b'·Cs with fixed made-up coefficients (all positive for
// Cs ≥ 0 so the magnitude is the value itself).
struct LinearModel {
  std::vector<std::vector<double>> ah, bh, ap, bp;
  RaoPrediction operator()(double Cs, int c) const {
    RaoPrediction r;
    for (std::size_t i = 0; i < ah[c].size(); ++i) {
      r.heave.emplace_back(ah[c][i] + bh[c][i] * Cs, 0.0);
      r.pitch.emplace_back(ap[c][i] + bp[c][i] * Cs, 0.0);
    }
    return r;
  }
};

CalibrationCase MakeCase(const std::string& label, std::vector<double> heave, std::vector<double> pitch,
                         double hull_parameter = 0.0) {
  CalibrationCase c;
  c.label = label;
  c.Fn = 0.75;
  c.hull_parameter = hull_parameter;
  for (std::size_t i = 0; i < heave.size(); ++i) {
    TankRaoPoint p;
    p.Fn = 0.75;
    p.has_omega_e = true;
    p.omega_e_rad_s = 5.0 + i;
    p.heave_amp = heave[i];
    p.pitch_amp = pitch[i];
    p.source = label + ":" + std::to_string(i + 2);
    c.points.push_back(p);
  }
  return c;
}

LinearModel Model1() {
  LinearModel m;
  m.ah = {{1.0, 1.5, 2.0, 1.2}};
  m.bh = {{-3.0, -8.0, -12.0, -5.0}};  // the RAO falls with damping
  m.ap = {{0.8, 1.1, 1.3, 0.9}};
  m.bp = {{-2.0, -4.0, -6.0, -3.0}};
  return m;
}
// Measured values (made up, near the model at Cs ≈ 0.05).
const std::vector<double> kHeave = {0.86, 1.09, 1.42, 0.93};
const std::vector<double> kPitch = {0.71, 0.93, 1.02, 0.76};
}  // namespace

TEST_CASE("single Cs: weighted linear least squares in closed form", "[calibration]") {
  const LinearModel m = Model1();
  CsCalibrationOptions o;
  o.heave_weight = 1.0;
  o.pitch_weight = 2.0;
  const auto r = CalibrateCs(m, {MakeCase("A", kHeave, kPitch)}, o);

  // Closed form: r_i = w (a_i + b_i Cs − y_i); Cs = Σ w² b (y − a) / Σ w² b², var = σ̂² / Σ w² b²,
  // σ̂² = Σ r² / (n − 1).
  double num = 0, den = 0;
  for (int i = 0; i < 4; ++i) {
    num += 1.0 * m.bh[0][i] * (kHeave[i] - m.ah[0][i]) + 4.0 * m.bp[0][i] * (kPitch[i] - m.ap[0][i]);
    den += 1.0 * m.bh[0][i] * m.bh[0][i] + 4.0 * m.bp[0][i] * m.bp[0][i];
  }
  const double Cs = num / den;
  double ss = 0;
  for (int i = 0; i < 4; ++i) {
    ss += std::pow(m.ah[0][i] + m.bh[0][i] * Cs - kHeave[i], 2) +
          4.0 * std::pow(m.ap[0][i] + m.bp[0][i] * Cs - kPitch[i], 2);
  }
  const double s2 = ss / (8 - 1);
  REQUIRE(r.num_residuals == 8);
  REQUIRE(r.num_parameters == 1);
  CHECK(r.parameters[0] == Approx(Cs).epsilon(kFitTol));
  CHECK(r.parameter_std_errors[0] == Approx(std::sqrt(s2 / den)).epsilon(kStdErrTol));
  CHECK(r.reduced_chi_square == Approx(s2).epsilon(kStdErrTol));
  CHECK(r.residual_variance == Approx(s2).epsilon(kStdErrTol));
  CHECK(r.rms_residual == Approx(std::sqrt(ss / 8)).epsilon(kStdErrTol));
  CHECK(r.converged);
  CHECK(r.covariance_ok);
  CHECK(r.case_Cs[0] == r.parameters[0]);
  // The per-case prediction cache: one model call per distinct Cs (base and ±h per Jacobian, trial steps),
  // not one per residual block. Without it this fit (8 blocks) would take 8× as many calls.
  CHECK(r.model_evaluations < 8 * 3);
  REQUIRE(r.residuals.size() == 8);
  CHECK(r.residuals[1].quantity == "pitch");
  CHECK(r.residuals[1].residual_after ==
        Approx(2.0 * (m.ap[0][0] + m.bp[0][0] * Cs - kPitch[0])).epsilon(kStdErrTol));
  CHECK(r.residuals[1].source == "A:2");
  CHECK_FALSE(r.BriefReport().empty());
  CHECK(r.FullReport().find("2*cost/(n - p)") != std::string::npos);
}

TEST_CASE("zero weight leaves a quantity out", "[calibration]") {
  const LinearModel m = Model1();
  CsCalibrationOptions o;
  o.pitch_weight = 0.0;
  const auto r = CalibrateCs(m, {MakeCase("A", kHeave, kPitch)}, o);
  double num = 0, den = 0;
  for (int i = 0; i < 4; ++i) {
    num += m.bh[0][i] * (kHeave[i] - m.ah[0][i]);
    den += m.bh[0][i] * m.bh[0][i];
  }
  CHECK(r.num_residuals == 4);
  CHECK(r.parameters[0] == Approx(num / den).epsilon(kFitTol));
}

TEST_CASE("per speed: independent closed forms with a pooled residual variance", "[calibration]") {
  LinearModel m = Model1();
  m.ah.push_back({0.9, 1.4, 1.7});
  m.bh.push_back({-2.0, -6.0, -9.0});
  m.ap.push_back({0.7, 1.0, 1.2});
  m.bp.push_back({-1.0, -3.0, -5.0});
  const std::vector<CalibrationCase> cases = {MakeCase("A", kHeave, kPitch),
                                              MakeCase("B", {0.75, 1.02, 1.31}, {0.62, 0.83, 0.93})};
  CsCalibrationOptions o;
  o.mode = CsFitMode::kPerCase;
  const auto r = CalibrateCs(m, cases, o);
  REQUIRE(r.num_parameters == 2);
  REQUIRE(r.num_residuals == 14);
  double ss = 0;
  std::vector<double> Cs(2), den(2);
  for (int c = 0; c < 2; ++c) {
    double num = 0;
    for (std::size_t i = 0; i < m.ah[c].size(); ++i) {
      num += m.bh[c][i] * (cases[c].points[i].heave_amp - m.ah[c][i]) +
             m.bp[c][i] * (cases[c].points[i].pitch_amp - m.ap[c][i]);
      den[c] += m.bh[c][i] * m.bh[c][i] + m.bp[c][i] * m.bp[c][i];
    }
    Cs[c] = num / den[c];
    for (std::size_t i = 0; i < m.ah[c].size(); ++i) {
      ss += std::pow(m.ah[c][i] + m.bh[c][i] * Cs[c] - cases[c].points[i].heave_amp, 2) +
            std::pow(m.ap[c][i] + m.bp[c][i] * Cs[c] - cases[c].points[i].pitch_amp, 2);
    }
  }
  const double s2 = ss / (14 - 2);
  for (int c = 0; c < 2; ++c) {
    CHECK(r.parameters[c] == Approx(Cs[c]).epsilon(kFitTol));
    CHECK(r.parameter_std_errors[c] == Approx(std::sqrt(s2 / den[c])).epsilon(kStdErrTol));
  }
  CHECK(r.parameter_names[1] == "Cs[B]");
}

TEST_CASE("Cs = a + b p across hulls: two-parameter regression with Eigen", "[calibration]") {
  LinearModel m = Model1();
  m.ah.push_back({0.9, 1.4, 1.7});
  m.bh.push_back({-2.0, -6.0, -9.0});
  m.ap.push_back({0.7, 1.0, 1.2});
  m.bp.push_back({-1.0, -3.0, -5.0});
  m.ah.push_back({1.1, 1.6});
  m.bh.push_back({-4.0, -10.0});
  m.ap.push_back({0.9, 1.2});
  m.bp.push_back({-2.5, -5.0});
  const std::vector<CalibrationCase> cases = {MakeCase("A", kHeave, kPitch, 1.5),
                                              MakeCase("B", {0.75, 1.02, 1.31}, {0.62, 0.83, 0.93}, 2.0),
                                              MakeCase("C", {0.95, 1.18}, {0.78, 0.97}, 3.0)};
  CsCalibrationOptions o;
  o.mode = CsFitMode::kLinearInParameter;
  o.slope_initial = 0.01;
  const auto r = CalibrateCs(m, cases, o);
  // Rows: b_i·[1, p] (a + b p) = y − a_i.
  Eigen::MatrixXd X(18, 2);
  Eigen::VectorXd y(18);
  int row = 0;
  for (int c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < m.ah[c].size(); ++i) {
      const double p = cases[c].hull_parameter;
      X.row(row) << m.bh[c][i], m.bh[c][i] * p;
      y(row++) = cases[c].points[i].heave_amp - m.ah[c][i];
      X.row(row) << m.bp[c][i], m.bp[c][i] * p;
      y(row++) = cases[c].points[i].pitch_amp - m.ap[c][i];
    }
  }
  const Eigen::Vector2d beta = (X.transpose() * X).ldlt().solve(X.transpose() * y);
  const double s2 = (X * beta - y).squaredNorm() / (18 - 2);
  const Eigen::Matrix2d C = (X.transpose() * X).inverse() * s2;
  REQUIRE(r.num_parameters == 2);
  CHECK(r.parameters[0] == Approx(beta(0)).epsilon(kFitTol));
  CHECK(r.parameters[1] == Approx(beta(1)).epsilon(kFitTol));
  CHECK(r.parameter_std_errors[0] == Approx(std::sqrt(C(0, 0))).epsilon(kStdErrTol));
  CHECK(r.parameter_std_errors[1] == Approx(std::sqrt(C(1, 1))).epsilon(kStdErrTol));
  CHECK(r.covariance[0][1] == Approx(C(0, 1)).epsilon(kStdErrTol));
  // Propagated Cs of hull B: var(a + b p) = C00 + 2 p C01 + p² C11.
  const double p = 2.0;
  CHECK(r.case_Cs[1] == Approx(beta(0) + beta(1) * p).epsilon(kFitTol));
  CHECK(r.case_Cs_std_error[1] ==
        Approx(std::sqrt(C(0, 0) + 2 * p * C(0, 1) + p * p * C(1, 1))).epsilon(kStdErrTol));
}

TEST_CASE("Huber loss: the M-estimator equation solved by bisection", "[calibration][robust]") {
  // Heave only, one gross outlier in point 2.
  LinearModel m = Model1();
  std::vector<double> heave = kHeave;
  heave[2] = 2.2;
  CsCalibrationOptions o;
  o.pitch_weight = 0.0;
  o.loss = CsRobustLoss::kHuber;
  o.loss_scale = 0.05;
  const auto r = CalibrateCs(m, {MakeCase("A", heave, kPitch)}, o);
  // Ceres' Huber: ρ(s) = s (s ≤ δ²), 2δ√s − δ² otherwise, s = r². Stationary point of ½Σρ(r_i²):
  // Σ ψ(r_i) b_i = 0 with ψ(r) = clamp(r, −δ, δ). Monotone in Cs, so bisection finds it.
  const double delta = o.loss_scale;
  auto g = [&](double Cs) {
    double sum = 0;
    for (int i = 0; i < 4; ++i) {
      const double res = m.ah[0][i] + m.bh[0][i] * Cs - heave[i];
      sum += std::max(-delta, std::min(delta, res)) * m.bh[0][i];
    }
    return sum;
  };
  double lo = 0.0, hi = 0.2;
  REQUIRE(g(lo) * g(hi) < 0);
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (g(lo) * g(mid) <= 0 ? hi : lo) = mid;
  }
  CHECK(r.parameters[0] == Approx(0.5 * (lo + hi)).epsilon(kRobustFitTol));
  // Cauchy runs and down-weights the outlier too: closer to the fit without the outlier than plain LS.
  o.loss = CsRobustLoss::kCauchy;
  const auto rc = CalibrateCs(m, {MakeCase("A", heave, kPitch)}, o);
  o.loss = CsRobustLoss::kNone;
  const auto plain = CalibrateCs(m, {MakeCase("A", heave, kPitch)}, o);
  const auto clean = CalibrateCs(m, {MakeCase("A", kHeave, kPitch)}, o);
  CHECK(std::fabs(rc.parameters[0] - clean.parameters[0]) <
        std::fabs(plain.parameters[0] - clean.parameters[0]));
}

TEST_CASE("bound Cs >= 0 holds and is reported", "[calibration]") {
  // Data above the model at Cs = 0 with RAOs falling with Cs: the unconstrained optimum is negative.
  const LinearModel m = Model1();
  CsCalibrationOptions o;
  const auto r = CalibrateCs(m, {MakeCase("A", {1.1, 1.6, 2.1, 1.3}, {0.9, 1.2, 1.4, 1.0})}, o);
  CHECK(r.parameters[0] >= 0.0);
  CHECK(r.parameters[0] < 1e-9);
  REQUIRE_FALSE(r.warnings.empty());
  CHECK(r.warnings[0].find("lower bound") != std::string::npos);
}

TEST_CASE("phases: noise-free complex data recovered exactly", "[calibration][phase]") {
  CalibrationCase c = MakeCase("A", {1, 1, 1, 1, 1, 1}, {1, 1, 1, 1, 1, 1});
  for (std::size_t i = 0; i < c.points.size(); ++i) c.points[i].omega_e_rad_s = 6.0 + 0.8 * i;
  const auto model = MakeSyntheticOscillatorModel({}, {c});
  const auto truth = model(0.07, 0);
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    auto& p = c.points[i];
    p.heave_amp = std::abs(truth.heave[i]);
    p.pitch_amp = std::abs(truth.pitch[i]);
    p.has_heave_phase = p.has_pitch_phase = true;
    p.heave_phase_deg = std::arg(truth.heave[i]) * 180 / M_PI;
    p.pitch_phase_deg = std::arg(truth.pitch[i]) * 180 / M_PI;
  }
  CsCalibrationOptions o;
  o.use_phases = true;
  const auto r = CalibrateCs(model, {c}, o);
  CHECK(r.num_residuals == 24);
  CHECK(r.parameters[0] == Approx(0.07).epsilon(kFitTol));
  CHECK(r.rms_residual < 1e-8);
  // The heave peak moves with Cs: after the fit it matches the measured (= generated) peak.
  REQUIRE(r.peaks.size() == 2);
  CHECK(r.peaks[0].after.value == Approx(r.peaks[0].measured.value).epsilon(kFitTol));
  CHECK(std::fabs(r.peaks[0].RelativeErrorBefore()) > 0.01);
}

TEST_CASE("invalid options are refused with the field and rule", "[calibration][bad-input]") {
  std::string e;
  CsCalibrationOptions o;
  REQUIRE(o.IsValid(&e));
  o.heave_weight = -1;
  CHECK_FALSE(o.IsValid(&e));
  CHECK(e.find("heave_weight = -1") != std::string::npos);
  o = {};
  o.heave_weight = o.pitch_weight = 0;
  CHECK_FALSE(o.IsValid(&e));
  o = {};
  o.loss = CsRobustLoss::kHuber;
  o.loss_scale = 0;
  CHECK_FALSE(o.IsValid(&e));
  CHECK(e.find("loss_scale") != std::string::npos);
  o = {};
  o.Cs_initial = -0.1;
  CHECK_FALSE(o.IsValid(&e));
  CHECK(e.find("Cs_initial") != std::string::npos);
  CHECK_THROWS_AS(CalibrateCs(Model1(), {MakeCase("A", kHeave, kPitch)}, o), std::invalid_argument);
}

TEST_CASE("data that cannot determine the parameters is refused", "[calibration][bad-input]") {
  std::string e;
  CsCalibrationOptions o;
  o.pitch_weight = 0;
  // One point, heave only: 1 residual for 1 parameter.
  CHECK_FALSE(CheckCalibrationData({MakeCase("A", {1.0}, {1.0})}, o, &e));
  CHECK(e.find("1 residual(s) for 1 fitted parameter(s)") != std::string::npos);
  CHECK_THROWS_WITH(CalibrateCs(Model1(), {MakeCase("A", {1.0}, {1.0})}, o), Catch::Contains("n > p"));
  o = {};
  o.mode = CsFitMode::kPerCase;
  CHECK_FALSE(CheckCalibrationData({MakeCase("A", kHeave, kPitch), MakeCase("B", {}, {})}, o, &e));
  CHECK(e.find("'B' has no measured points") != std::string::npos);
  o.pitch_weight = 0;
  CHECK_FALSE(CheckCalibrationData({MakeCase("A", kHeave, kPitch), MakeCase("B", {1.0}, {1.0})}, o, &e));
  CHECK(e.find("case 'B' gives 1 residual(s)") != std::string::npos);
  o = {};
  o.mode = CsFitMode::kLinearInParameter;
  CHECK_FALSE(
      CheckCalibrationData({MakeCase("A", kHeave, kPitch, 2), MakeCase("B", kHeave, kPitch, 2)}, o, &e));
  CHECK(e.find("at least two hulls") != std::string::npos);
  o = {};
  o.residual_scale = CsResidualScale::kRelative;
  CHECK_FALSE(CheckCalibrationData({MakeCase("A", {1.0, 0.0}, {1.0, 1.0})}, o, &e));
  CHECK(e.find("A:3: heave_rao = 0") != std::string::npos);
  o = {};
  o.use_phases = true;
  CHECK_FALSE(CheckCalibrationData({MakeCase("A", kHeave, kPitch)}, o, &e));
  CHECK(e.find("use_phases") != std::string::npos);
  CHECK_FALSE(CheckCalibrationData({}, {}, &e));
}

TEST_CASE("a model returning the wrong number of points is a domain error", "[calibration][bad-input]") {
  CsRaoModel bad = [](double, int) { return RaoPrediction{{1.0}, {1.0}}; };
  CHECK_THROWS_AS(CalibrateCs(bad, {MakeCase("A", kHeave, kPitch)}, {}), std::domain_error);
  CsRaoModel nan = [](double, int) {
    RaoPrediction r;
    r.heave.assign(4, std::complex<double>(std::nan(""), 0));
    r.pitch.assign(4, 1.0);
    return r;
  };
  CHECK_THROWS_AS(CalibrateCs(nan, {MakeCase("A", kHeave, kPitch)}, {}), std::domain_error);
}

TEST_CASE("a model that refuses Cs < 0 works at the bound (extrapolation below 0)", "[calibration]") {
  // Like the strip solver's MotionOptions::IsValid: Cs must be >= 0. Data above the model at Cs = 0, so the
  // optimum is on the bound and Ceres' central difference there asks for Cs = −h.
  const LinearModel lin = Model1();
  CsRaoModel strict = [lin](double Cs, int c) {
    if (Cs < 0) throw std::invalid_argument("Cs = " + std::to_string(Cs) + ": must be >= 0");
    return lin(Cs, c);
  };
  const auto data = MakeCase("A", {1.1, 1.6, 2.1, 1.3}, {0.9, 1.2, 1.4, 1.0});
  const auto r = CalibrateCs(strict, {data}, {});
  CHECK(r.parameters[0] < 1e-9);
  for (const auto& w : r.warnings) CHECK(w.find("failed") == std::string::npos);  // never called below 0
  // The same fit with the unrestricted model gives the same answer.
  const auto free = CalibrateCs(lin, {data}, {});
  CHECK(r.parameters[0] == Approx(free.parameters[0]).margin(1e-12));
  CHECK(r.parameter_std_errors[0] == Approx(free.parameter_std_errors[0]).epsilon(kStdErrTol));
}

TEST_CASE("a model that throws during the fit: reported, never escaping Ceres unhandled", "[calibration]") {
  const LinearModel lin = Model1();
  // The least-squares optimum of the data is Cs ≈ 0.05 (closed form in the first test), but the model has no
  // solution below 0.08: Ceres' steps towards the optimum fail. Either Ceres stops at a usable point (then
  // the failures are in the warnings) or CalibrateCs throws std::domain_error carrying the model's message;
  // the model's exception must not cross Ceres.
  CsRaoModel picky = [lin](double Cs, int c) {
    if (Cs < 0.08) throw std::domain_error("no solution below 0.08");
    return lin(Cs, c);
  };
  CsCalibrationOptions o;
  o.Cs_initial = 0.12;
  try {
    const auto r = CalibrateCs(picky, {MakeCase("A", kHeave, kPitch)}, o);
    CHECK(r.parameters[0] >= 0.08);
    REQUIRE_FALSE(r.warnings.empty());
    CHECK(r.warnings.front().find("no solution below 0.08") != std::string::npos);
  } catch (const std::domain_error& e) {
    CHECK(std::string(e.what()).find("no solution below 0.08") != std::string::npos);
  }
  // A model failing at the start value is a domain error naming the case.
  o.Cs_initial = 0.05;
  CHECK_THROWS_WITH(CalibrateCs(picky, {MakeCase("A", kHeave, kPitch)}, o),
                    Catch::Contains("case 'A'") && Catch::Contains("no solution below 0.08"));
}

TEST_CASE("an all-zero measured quantity gives no peak comparison (no division by zero)", "[calibration]") {
  CsCalibrationOptions o;
  o.pitch_weight = 0;
  const auto r = CalibrateCs(Model1(), {MakeCase("A", kHeave, {0, 0, 0, 0})}, o);
  REQUIRE(r.peaks.size() == 1);
  CHECK(r.peaks[0].quantity == "heave");
  REQUIRE_FALSE(r.warnings.empty());
  CHECK(r.warnings.back().find("every measured pitch RAO is 0") != std::string::npos);
}

TEST_CASE("too few points per parameter is a warning, not a silent 'converged'", "[calibration]") {
  // One tank row: a heave and a pitch residual for one parameter, below the stated minimum of 3 per parameter.
  LinearModel m;
  m.ah = {{1.0}};
  m.bh = {{-3.0}};
  m.ap = {{0.8}};
  m.bp = {{-2.0}};
  const auto r = CalibrateCs(m, {MakeCase("A", {0.85}, {0.7})}, CsCalibrationOptions{});
  bool warned = false;
  for (const auto& w : r.warnings) warned = warned || w.find("fewer than 3 per parameter") != std::string::npos;
  CHECK(warned);
}
