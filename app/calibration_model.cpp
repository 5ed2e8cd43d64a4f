#include "app/calibration_model.h"

#include <algorithm>
#include <memory>

#include <cmath>

#include "app/design_case.h"
#include "app/run_checks.h"
#include "io/input_error.h"
#include "optimizer/synthetic_oscillator_rao.h"
#include "optimizer/tank_rao_frequency.h"
#include "seakeeping/motions/validity_range.h"

namespace hullopt::app {
namespace {

// The paper's method for the config's own hull: the strip kernels do not depend on Cs, so they are built once
// per speed; each model call is then a 2×2 solve per measured frequency.
opt::CsRaoModel StripSolverModel(io::YamlMap& root, const io::CalibrateHull& hull,
                                 const std::vector<opt::CalibrationCase>& mine, std::vector<std::string>* warnings) {
  if (!hull.name.empty())
    throw io::InputError(root.file() + ": calibrate.hulls['" + hull.name +
                         "']: the strip solver calibrates the config's own hull (the calibrate.data form); "
                         "calibrate several hulls with one config each, or give each a test model");
  const DesignCase base = LoadDesignCase(root, root.file(), "calibration hull", /*read_speed=*/false);
  // One kernel per speed, all built and held before the fit; each Cs trial of the fit (at most 100
  // trust-region iterations with a derivative each: 300 sweeps) is a 2 x 2 solve per measured point.
  io::StripWork work = io::StripWorkFromResolved(root.resolved(), 1);
  work.frequencies = 1;
  for (const auto& c : mine) work.frequencies = std::max<long>(work.frequencies, static_cast<long>(c.points.size()));
  work.kernels = static_cast<long>(mine.size());
  work.parallel = static_cast<int>(mine.size());
  work.sweeps_per_kernel = 300;
  work.count_key = work.parallel_key = "calibrate.speeds_Fn";
  CheckRunCost("calibrate", work);
  struct Speed {
    DesignCase design;
    sk::StripKernel kernel;
    opt::CaseFrequencyGrid grid;
  };
  auto speeds = std::make_shared<std::vector<Speed>>();
  for (const auto& c : mine) {
    Speed s{base, {}, {}};
    s.design.speed_m_s = c.Fn * std::sqrt(base.water.g_m_s2 * base.hydrostatics.L_m);
    s.kernel = BuildDesignKernel(s.design);
    s.grid = opt::WaveFrequencyGrid(c, base.hydrostatics.L_m, base.water.g_m_s2);
    if (warnings && base.solver.method == "time_domain_strip")
      for (const auto& w : sk::ValidityWarnings(s.design.speed_m_s, base.hydrostatics.L_m, base.water.g_m_s2,
                                                s.grid.omega_rad_s))
        warnings->push_back("case '" + c.label + "': " + w);
    speeds->push_back(std::move(s));
  }
  return [speeds](double Cs, int local) {
    const Speed& s = speeds->at(local);
    const sk::RaoTable rao = DesignRaosFromKernel(s.design, s.kernel, s.grid.omega_rad_s, Cs);
    opt::RaoPrediction p;
    for (int i : s.grid.index_of_point) {
      p.heave.push_back(rao.heave.at(i));
      p.pitch.push_back(rao.pitch.at(i));
    }
    return p;
  };
}

}  // namespace

opt::CsRaoModel MakeCalibrationModel(io::YamlMap& root, const io::CalibrateConfig& config,
                                     const std::vector<opt::CalibrationCase>& cases,
                                     std::vector<std::string>* warnings) {
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
      part.model = StripSolverModel(root, hull, mine, warnings);
    }
    parts->push_back(std::move(part));
  }
  return [parts, route](double Cs, int case_index) {
    const auto [p, local] = route->at(case_index);
    return (*parts)[p].model(Cs, local);
  };
}

}  // namespace hullopt::app
