#include "calibration/calibration_model.h"

#include <algorithm>

#include "calibration/model/strip_rao_model.h"
#include "io/config/design_config.h"
#include "io/formats/input_error.h"
#include "calibration/fit/synthetic_oscillator_rao.h"

namespace hullopt::calib {

CsRaoModel MakeCalibrationModel(io::YamlMap& root, const CalibrateConfig& config,
                                     const std::vector<opt::CalibrationCase>& cases,
                                     std::vector<std::string>* warnings,
                                     const std::function<void(const io::StripWork&)>& check_cost) {
  std::vector<CsModelPart> parts;
  for (const auto& hull : config.hulls) {
    CsModelPart part;
    std::vector<opt::CalibrationCase> mine;
    for (int c = 0; c < static_cast<int>(cases.size()); ++c) {
      if (cases[c].hull != hull.name) continue;
      part.cases.push_back(c);
      mine.push_back(cases[c]);
    }
    if (hull.synthetic) {
      part.model = MakeSyntheticOscillatorModel(*hull.synthetic, mine);
    } else {
      if (!hull.name.empty())
        throw io::InputError(root.file() + ": calibrate.hulls['" + hull.name +
                             "']: the strip solver calibrates the config's own hull (the calibrate.data form); "
                             "calibrate several hulls with one config each, or give each a test model");
      io::DesignReadOptions read;
      read.read_speed = false;  // one design per measured speed
      io::ParsedDesign parsed = io::ParseDesign(root, root.file(), "calibration hull", read);
      root.Finish();  // the whole config read and checked before the hull is built and the kernels
      const eval::DesignCase base = io::BuildParsedDesign(parsed);
      // One kernel per speed, all built and held before the fit; each Cs trial of the fit (at most 100
      // trust-region iterations with a derivative each: 300 sweeps) is a 2 x 2 solve per measured point.
      io::StripWork work = io::StripWorkFromResolved(root.resolved(), 1);
      work.frequencies = 1;
      for (const auto& c : mine)
        work.frequencies = std::max<long>(work.frequencies, static_cast<long>(c.points.size()));
      work.kernels = static_cast<long>(mine.size());
      work.parallel = static_cast<int>(mine.size());
      work.sweeps_per_kernel = 300;
      work.count_key = work.parallel_key = "calibrate.speeds_Fn";
      // Strip theory has no kernel to reuse and is refused by the model below: no estimate for it.
      if (base.solver.rao.method == sk::RaoSolverOptions::Method::kTimeDomainStrip && check_cost) check_cost(work);
      part.model = StripSolverCsModel(base, mine, warnings);
    }
    parts.push_back(std::move(part));
  }
  return CombineCsModels(std::move(parts));
}

}  // namespace hullopt::calib
