#include "calibration/calibration_output.h"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hullopt/version.h"

namespace hullopt::calib {
namespace {

nlohmann::json Peak(const opt::RaoPeak& p) {
  return {{"x", p.x}, {"value", p.value}, {"at_edge", p.at_edge}};
}

std::string F(double v, const char* f = "%.6g") {
  char b[32];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

std::string CalibrationJson(const CalibrateConfig& config, const std::vector<opt::CalibrationCase>& cases,
                            const CsCalibrationResult& r) {
  using nlohmann::json;
  json j;
  j["hullopt_version"] = kVersion;
  j["conventions"] =
      "heave |x3|/A [m/m], pitch |x5|/(kA) [-], k = omega^2/g, phases [deg] lead positive relative to the "
      "wave "
      "crest at the CG; residuals weighted (see residual_scale and weights)";
  j["mode"] = ToString(r.mode);
  if (r.mode == CsFitMode::kSingle) {
    j["Cs"] = r.parameters[0];
    j["Cs_std_error"] = r.parameter_std_errors[0];
  } else {
    j["Cs"] = r.case_Cs;
    j["Cs_std_error"] = r.case_Cs_std_error;
  }
  j["rms_residual"] = r.rms_residual;
  j["rms_residual_before"] = r.rms_residual_before;
  j["reduced_chi_square"] = r.reduced_chi_square;
  j["residual_variance"] = r.residual_variance;
  j["uncertainty_convention"] =
      "std_error = sqrt(diag((J^T J)^-1) * s2), Ceres covariance at the solution (robustified Jacobian with "
      "a loss), "
      "s2 = 2*final_cost/(n - p); reduced_chi_square = sum(r^2)/(n - p) and rms_residual = sqrt(sum(r^2)/n) "
      "without the robust loss";
  j["num_residuals"] = r.num_residuals;
  j["num_parameters"] = r.num_parameters;
  j["converged"] = r.converged;
  j["covariance_ok"] = r.covariance_ok;
  j["Cs_initial"] = config.options.Cs_initial;
  j["residual_scale"] = ToString(config.options.residual_scale);
  j["weights"] = {{"heave", config.options.heave_weight}, {"pitch", config.options.pitch_weight}};
  j["loss"] = {{"type", ToString(config.options.loss)}, {"scale", config.options.loss_scale}};
  j["use_phases"] = config.options.use_phases;
  j["parameter_name"] = config.parameter_name;
  json params = json::array();
  for (std::size_t i = 0; i < r.parameters.size(); ++i) {
    params.push_back({{"name", r.parameter_names[i]},
                      {"value", r.parameters[i]},
                      {"std_error", r.parameter_std_errors[i]}});
  }
  j["parameters"] = params;
  j["covariance"] = r.covariance;
  json jc = json::array();
  for (std::size_t c = 0; c < cases.size(); ++c) {
    json e = {{"label", cases[c].label},
              {"hull", cases[c].hull},
              {"Fn", cases[c].Fn},
              {"hull_parameter", cases[c].hull_parameter},
              {"points", cases[c].points.size()},
              {"Cs", r.case_Cs[c]},
              {"Cs_std_error", r.case_Cs_std_error[c]}};
    json peaks = json::object();
    for (const auto& pk : r.peaks) {
      if (pk.case_index != static_cast<int>(c)) continue;
      peaks[pk.quantity] = {{"abscissa", pk.abscissa},
                            {"measured", Peak(pk.measured)},
                            {"before", Peak(pk.before)},
                            {"after", Peak(pk.after)},
                            {"relative_error_before", pk.RelativeErrorBefore()},
                            {"relative_error_after", pk.RelativeErrorAfter()}};
    }
    e["peaks"] = peaks;
    jc.push_back(e);
  }
  j["cases"] = jc;
  json res = json::array();
  for (const auto& p : r.residuals) {
    res.push_back({{"case", p.case_index},
                   {"point", p.point_index},
                   {"source", p.source},
                   {"quantity", p.quantity},
                   {"measured", p.measured},
                   {"computed_before", p.computed_before},
                   {"computed_after", p.computed_after},
                   {"residual_before", p.residual_before},
                   {"residual_after", p.residual_after}});
  }
  j["residuals"] = res;
  j["warnings"] = r.warnings;
  j["ceres"] = r.ceres_brief;
  j["fit_seconds"] = r.fit_seconds;
  j["model_evaluations"] = r.model_evaluations;
  return j.dump(2) + "\n";
}

std::string CalibratedSolverYaml(const CalibrateConfig& config,
                                 const std::vector<opt::CalibrationCase>& cases,
                                 const CsCalibrationResult& r, int c) {
  std::ostringstream s;
  s << "# hullopt " << kVersion << " calibrate: sectional damping coefficient Cs fitted to tank RAOs\n"
    << "# case: " << cases[c].label << " (" << cases[c].points.size() << " measured points)\n"
    << "# mode " << ToString(r.mode) << ", standard error " << F(r.case_Cs_std_error[c], "%.3g")
    << " (1 sigma), rms residual " << F(r.rms_residual_before, "%.4g") << " -> " << F(r.rms_residual, "%.4g")
    << ", reduced chi-square " << F(r.reduced_chi_square, "%.4g") << "\n";
  if (r.mode == CsFitMode::kLinearInParameter) {
    s << "# law: Cs = " << F(r.parameters[0]) << " + " << F(r.parameters[1]) << " * " << config.parameter_name
      << " (" << config.parameter_name << " = " << F(cases[c].hull_parameter) << " here)\n";
  }
  s << "# Paste into the hull config (merge with its other solver keys).\n"
    << "solver:\n  Cs: " << F(r.case_Cs[c], "%.6g") << "\n";
  return s.str();
}

}  // namespace hullopt::calib
