// hullopt calibrate CONFIG --out DIR: fits the damping coefficient Cs to tank RAOs (docs/calibration.md). Linked
// into hullopt-calibrate and the Python module only (app/calibrate_command.h).
#include <glog/logging.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "app/calibrate_command.h"
#include "app/output_dir.h"
#include "app/output_options.h"
#include "app/run_checks.h"
#include "calibration/calibrate_config.h"
#include "calibration/calibration_model.h"
#include "calibration/calibration_output.h"
#include "calibration/calibration_plot.h"
#include "evaluation/validity_envelope.h"
#include "io/formats/atomic_file.h"
#include "io/formats/input_error.h"
#include "io/formats/tank_rao_reader.h"

namespace hullopt::app {
namespace {

void Write(const std::string& path, const std::string& text) {
  io::WriteFileAtomically(path, text);
}

/// "Fn 0.75" → "Fn0.75", "hull A Fn 0.5" → "hull_A_Fn0.5": a file-name-safe label.
std::string FileLabel(const std::string& label) {
  std::string s;
  for (std::size_t i = 0; i < label.size(); ++i) {
    const char c = label[i];
    if (c == ' ') {
      if (i >= 2 && label.compare(i - 2, 2, "Fn") == 0) continue;
      s += '_';
    } else if (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-') {
      s += c;
    } else {
      s += '_';
    }
  }
  return s;
}

}  // namespace

void RunCalibrate(const std::string& config_file, const std::string& out_dir) {
  io::YamlMap root = io::YamlMap::LoadFile(config_file);
  const calib::CalibrateConfig cfg = calib::ReadCalibrateConfig(root);

  // Cases: hull by hull, speed by speed.
  std::vector<opt::CalibrationCase> cases;
  std::string files;
  for (const auto& hull : cfg.hulls) {
    std::vector<opt::TankRaoPoint> points;
    for (const auto& f : hull.data_files) {
      const auto pts = io::ReadTankRaoCsv(f);
      points.insert(points.end(), pts.begin(), pts.end());
      files += (files.empty() ? "" : ", ") + f;
    }
    const auto hc = io::GroupTankRaoBySpeed(points, cfg.speeds_Fn, hull.name, hull.parameter);
    cases.insert(cases.end(), hc.begin(), hc.end());
  }
  std::string error;
  if (!calib::CheckCalibrationData(cases, cfg.options, &error)) {
    throw io::InputError(config_file + ": calibrate data (" + files + "): " + error);
  }
  std::vector<std::string> validity;
  const calib::CsRaoModel model = calib::MakeCalibrationModel(
      root, cfg, cases, &validity, [](const io::StripWork& work) { CheckRunCost("calibrate", work); });
  root.Finish();

  // Ceres logs failed model evaluations through glog to stderr; CalibrateCs reports them in its warnings or
  // its exception instead, so keep the terminal to the one-line error rule.
  FLAGS_minloglevel = google::GLOG_FATAL;
  calib::CsCalibrationResult r;
  try {
    r = calib::CalibrateCs(model, cases, cfg.options);
  } catch (const std::invalid_argument& e) {
    throw io::InputError(config_file + ": " + e.what());
  } catch (const std::domain_error& e) {
    throw io::InputError(config_file + ": " + e.what());
  }

  r.warnings.insert(r.warnings.end(), validity.begin(), validity.end());
  // A fit is only offered for pasting when it is physical and determined: a fitted Cs outside the validity
  // envelope's range, or with a standard error larger than its value, is reported as not converged and gets no
  // calibrated_solver*.yaml.
  for (std::size_t c = 0; c < r.case_Cs.size(); ++c) {
    const std::string label = cases.size() > 1 && r.mode != calib::CsFitMode::kSingle ? " of case '" + cases[c].label + "'" : "";
    for (const auto& f : eval::CheckEnvelopeValue(eval::EnvelopeQuantity::kDampingCs, r.case_Cs[c], "Cs")) {
      r.converged = false;
      r.warnings.push_back("fitted " + f.message + label + ": the fit is not converged to a physical Cs");
    }
    if (c < r.case_Cs_std_error.size() && !(r.case_Cs_std_error[c] <= std::fabs(r.case_Cs[c]))) {
      r.converged = false;
      char buf[160];
      std::snprintf(buf, sizeof buf, " = %.4g has a standard error %.3g larger than its value", r.case_Cs[c],
                    r.case_Cs_std_error[c]);
      r.warnings.push_back("fitted Cs" + label + buf + ": the data do not determine it; the fit is not converged");
    }
    if (r.mode == calib::CsFitMode::kSingle) break;
  }
  if (!r.converged)
    r.warnings.push_back("the fit did not converge to a determined, physical Cs: no calibrated_solver*.yaml is "
                         "written (see calibration_report.txt)");
  PrepareOutputDir(out_dir, "calibrate", config_file, root.resolved());
  Write(OutPath(out_dir, "calibration.json"), calib::CalibrationJson(cfg, cases, r));
  Write(OutPath(out_dir, "calibration_report.txt"), r.FullReport());
  io::WriteSvg(calib::CalibrationPlot(cases, r, cfg.options.Cs_initial),
               OutPath(out_dir, "calibration_plot.svg"));
  std::vector<std::string> snippets;
  if (!r.converged) {
    // nothing to paste
  } else if (r.mode == calib::CsFitMode::kSingle) {
    snippets.push_back("calibrated_solver.yaml");
    Write(OutPath(out_dir, snippets.back()), calib::CalibratedSolverYaml(cfg, cases, r, 0));
  } else {
    for (int c = 0; c < static_cast<int>(cases.size()); ++c) {
      snippets.push_back("calibrated_solver_" + FileLabel(cases[c].label) + ".yaml");
      Write(OutPath(out_dir, snippets.back()), calib::CalibratedSolverYaml(cfg, cases, r, c));
    }
  }

  Out() << r.BriefReport() << "\n";
  for (const auto& pk : r.peaks) {
    Say("  %s %s peak: measured %.4g, computed %.4g (%+.1f%%) before, %.4g (%+.1f%%) after\n",
        cases[pk.case_index].label.c_str(), pk.quantity.c_str(), pk.measured.value, pk.before.value,
        100 * pk.RelativeErrorBefore(), pk.after.value, 100 * pk.RelativeErrorAfter());
  }
  for (const auto& w : r.warnings) std::cerr << "hullopt: warning: calibration: " << w << "\n";
  Out() << "wrote " << out_dir << "/{calibration.json, calibration_report.txt, calibration_plot.svg";
  for (const auto& s : snippets) Out() << ", " << s;
  Out() << ", config.resolved.yaml, VERSION}\n";
}

}  // namespace hullopt::app
