#include "app/calibration_model.h"

#include "evaluation/calibration_model.h"
#include "io/design_config.h"
#include "io/input_error.h"
#include "optimizer/synthetic_oscillator_rao.h"

namespace hullopt::app {

opt::CsRaoModel MakeCalibrationModel(io::YamlMap& root, const io::CalibrateConfig& config,
                                     const std::vector<opt::CalibrationCase>& cases,
                                     std::vector<std::string>* warnings) {
  std::vector<eval::CsModelPart> parts;
  for (const auto& hull : config.hulls) {
    eval::CsModelPart part;
    std::vector<opt::CalibrationCase> mine;
    for (int c = 0; c < static_cast<int>(cases.size()); ++c) {
      if (cases[c].hull != hull.name) continue;
      part.cases.push_back(c);
      mine.push_back(cases[c]);
    }
    if (hull.synthetic) {
      part.model = opt::MakeSyntheticOscillatorModel(*hull.synthetic, mine);
    } else {
      if (!hull.name.empty())
        throw io::InputError(root.file() + ": calibrate.hulls['" + hull.name +
                             "']: the strip solver calibrates the config's own hull (the calibrate.data form); "
                             "calibrate several hulls with one config each, or give each a test model");
      const eval::DesignCase base =
          io::LoadDesignCase(root, root.file(), "calibration hull", /*read_speed=*/false);
      part.model = eval::StripSolverCsModel(base, mine, warnings);
    }
    parts.push_back(std::move(part));
  }
  return eval::CombineCsModels(std::move(parts));
}

}  // namespace hullopt::app
