#include "calibration/calibrate_config.h"

#include "io/config/config_path.h"
#include "io/config/water_config.h"

namespace hullopt::calib {
namespace {

std::vector<std::string> DataFiles(io::YamlMap& m) {
  std::vector<std::string> files = ConfigFilePaths(m, "data");
  if (files.empty()) m.Fail("data", "must list at least one tank RAO CSV file");
  return files;
}

std::optional<SyntheticOscillatorOptions> Model(io::YamlMap& m) {
  if (!m.Has("model")) {
    m.Skip("model");
    return std::nullopt;
  }
  io::YamlMap model = m.Map("model");
  io::YamlMap s = model.Map("synthetic_oscillator");
  model.Finish();
  SyntheticOscillatorOptions o;
  o.heave_natural_rad_s = s.Number("heave_natural_rad_s", o.heave_natural_rad_s);
  o.pitch_natural_rad_s = s.Number("pitch_natural_rad_s", o.pitch_natural_rad_s);
  o.heave_zeta0 = s.Number("heave_zeta0", o.heave_zeta0);
  o.pitch_zeta0 = s.Number("pitch_zeta0", o.pitch_zeta0);
  o.heave_zeta_per_Cs = s.Number("heave_zeta_per_Cs", o.heave_zeta_per_Cs);
  o.pitch_zeta_per_Cs = s.Number("pitch_zeta_per_Cs", o.pitch_zeta_per_Cs);
  o.length_m = s.Number("length_m", o.length_m);
  o.g_m_s2 = s.Number("g_m_s2", o.g_m_s2);
  std::string error;
  if (!o.IsValid(&error)) model.Fail("synthetic_oscillator", error);
  s.Finish();
  return o;
}

}  // namespace

CalibrateConfig ReadCalibrateConfig(io::YamlMap& root) {
  CalibrateConfig cfg;
  io::YamlMap cal = root.Map("calibrate");

  // Speeds.
  if (cal.Has("speeds_Fn")) {
    cfg.speeds_Fn = cal.Numbers("speeds_Fn");
    root.Skip("speed");
    if (root.Has("speed")) cal.Fail("speeds_Fn", "give the speeds either here or in 'speed', not both");
  } else {
    cal.Skip("speeds_Fn");
    io::YamlMap speed = root.Map("speed");
    if (!speed.Has("Fn")) {
      speed.Fail(speed.Has("kn")    ? "kn"
                 : speed.Has("m_s") ? "m_s"
                                    : "Fn",
                 "calibrate matches the data's Fn column: give the speed as Fn (e.g. speed: { Fn: 0.75 })");
    }
    cfg.speeds_Fn = {speed.Number("Fn")};
    speed.Finish();
  }
  for (double fn : cfg.speeds_Fn)
    if (!(fn > 0)) cal.Fail(cal.Has("speeds_Fn") ? "speeds_Fn" : "calibrate", "Froude numbers must be > 0");

  // Options.
  CsCalibrationOptions& o = cfg.options;
  const std::string mode = cal.Choice("mode", {"single", "per_speed", "linear_in_parameter"}, "single");
  o.mode = mode == "single"      ? CsFitMode::kSingle
           : mode == "per_speed" ? CsFitMode::kPerCase
                                 : CsFitMode::kLinearInParameter;
  io::YamlMap w = cal.MapOrEmpty("weights");
  o.heave_weight = w.Number("heave", 1.0);
  o.pitch_weight = w.Number("pitch", 1.0);
  if (o.heave_weight < 0) w.Fail("heave", "must be >= 0 (0 leaves heave out of the fit)");
  if (o.pitch_weight < 0) w.Fail("pitch", "must be >= 0 (0 leaves pitch out of the fit)");
  if (o.heave_weight == 0 && o.pitch_weight == 0)
    w.Fail("heave", "heave and pitch weights are both 0: nothing to fit");
  w.Finish();
  o.residual_scale = cal.Choice("residual", {"absolute", "relative"}, "absolute") == "absolute"
                         ? CsResidualScale::kAbsolute
                         : CsResidualScale::kRelative;
  io::YamlMap loss = cal.MapOrEmpty("loss");
  const std::string type = loss.Choice("type", {"none", "huber", "cauchy"}, "none");
  o.loss = type == "none"    ? CsRobustLoss::kNone
           : type == "huber" ? CsRobustLoss::kHuber
                             : CsRobustLoss::kCauchy;
  o.loss_scale = loss.Number("scale", 1.0);
  if (!(o.loss_scale > 0))
    loss.Fail("scale", "must be > 0 (the residual size where the loss starts to down-weight)");
  loss.Finish();
  o.use_phases = cal.Boolean("use_phases", false);
  o.Cs_initial = cal.Number("Cs_initial", o.Cs_initial);
  if (o.Cs_initial < 0) cal.Fail("Cs_initial", "must be >= 0 (Cs is a damping coefficient)");
  RefuseOutsideEnvelope(cal, "Cs_initial", eval::EnvelopeQuantity::kDampingCs, o.Cs_initial);
  o.slope_initial = cal.Number("slope_initial", 0.0);
  o.max_iterations = cal.Integer("max_iterations", o.max_iterations);
  if (o.max_iterations < 1) cal.Fail("max_iterations", "must be >= 1");
  cfg.parameter_name = cal.String("parameter_name", "p");
  std::string error;
  if (!o.IsValid(&error)) throw io::InputError(cal.Where("mode") + ": " + error);

  // Hulls and data.
  if (cal.Has("data") == cal.Has("hulls")) {
    cal.Fail(cal.Has("data") ? "hulls" : "data",
             "give either 'data' (one hull: the config's) or 'hulls' (several hulls, each with its data)");
  }
  if (cal.Has("data")) {
    CalibrateHull h;
    h.data_files = DataFiles(cal);
    h.synthetic = Model(cal);
    cal.Skip("hulls");
    cfg.hulls.push_back(h);
  } else {
    cal.Skip("data");
    for (io::YamlMap& hm : cal.ListOfMaps("hulls")) {
      CalibrateHull h;
      h.name = hm.String("name");
      h.parameter = hm.Number("parameter", 0.0);
      h.data_files = DataFiles(hm);
      h.synthetic = Model(hm);
      hm.Finish();
      for (const auto& other : cfg.hulls)
        if (other.name == h.name) hm.Fail("name", "two hulls have this name");
      cfg.hulls.push_back(h);
    }
    if (cal.Has("model")) cal.Fail("model", "with 'hulls', give the model of each hull inside its entry");
    cal.Skip("model");
  }
  if (o.mode == CsFitMode::kLinearInParameter && cfg.hulls.size() < 2) {
    cal.Fail("mode",
             "linear_in_parameter fits Cs = a + b*p across hulls: list at least two 'hulls' with "
             "different 'parameter'");
  }
  cal.Finish();
  return cfg;
}

}  // namespace hullopt::calib
