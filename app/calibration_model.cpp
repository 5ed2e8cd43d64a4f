#include "app/calibration_model.h"

#include <memory>

#include "io/input_error.h"
#include "optimizer/synthetic_oscillator_rao.h"

namespace hullopt::app {

opt::CsRaoModel MakeCalibrationModel(io::YamlMap& root, const io::CalibrateConfig& config,
                                     const std::vector<opt::CalibrationCase>& cases) {
  // Per hull: its cases (in global order) and a model over them with local case indices.
  struct Part {
    opt::CsRaoModel model;
    std::vector<int> global;
  };
  auto parts = std::make_shared<std::vector<Part>>();
  auto route = std::make_shared<std::vector<std::pair<int, int>>>(cases.size());  // global → (part, local)
  for (const auto& hull : config.hulls) {
    Part part;
    std::vector<opt::CalibrationCase> mine;
    for (int c = 0; c < static_cast<int>(cases.size()); ++c) {
      if (cases[c].hull != hull.name) continue;
      (*route)[c] = {static_cast<int>(parts->size()), static_cast<int>(mine.size())};
      part.global.push_back(c);
      mine.push_back(cases[c]);
    }
    if (hull.synthetic) {
      part.model = opt::MakeSyntheticOscillatorModel(*hull.synthetic, mine);
    } else {
      // TODO(lead): build the strip model of this hull from root's hull/mass/water/solver sections (or from
      // the hull entry's own config), precompute its Cs-independent kernels once per speed, and return
      // [=](double Cs, int local) { 2×2 solve per measured frequency of mine[local] }.
      throw io::InputError(root.file() + ": calibrate" +
                           (hull.name.empty() ? "" : " hull '" + hull.name + "'") +
                           ": the strip solver is not wired to 'hullopt calibrate' in this version; give "
                           "calibrate.model.synthetic_oscillator (a test/demo model) to exercise the fit");
    }
    parts->push_back(std::move(part));
  }
  return [parts, route](double Cs, int case_index) {
    const auto [p, local] = route->at(case_index);
    return (*parts)[p].model(Cs, local);
  };
}

}  // namespace hullopt::app
