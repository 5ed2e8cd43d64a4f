#include "calibration/model/strip_rao_model.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "evaluation/strip_attitude.h"
#include "optimizer/tank_rao_frequency.h"
#include "seakeeping/motions/validity_range.h"

namespace hullopt::calib {

CsRaoModel StripSolverCsModel(const eval::DesignCase& base, const std::vector<opt::CalibrationCase>& cases,
                                   std::vector<std::string>* warnings) {
  struct Speed {
    eval::DesignCase design;
    sk::StripKernel kernel;
    opt::CaseFrequencyGrid grid;
  };
  auto speeds = std::make_shared<std::vector<Speed>>();
  for (const auto& c : cases) {
    Speed s{base, {}, {}};
    s.design.speed_m_s = c.Fn * std::sqrt(base.water.g_m_s2 * base.hydrostatics.L_m);
    if (base.solver.steady_flow) {  // each speed's own running attitude (the base holds hull.attitude)
      s.design.attitude = eval::StripAttitude(base.hull, base.mass, s.design.speed_m_s, base.water, base.solver,
                                        base.attitude, "calibration case '" + c.label + "'");
      s.design.running_hull = hull::ApplyRunningAttitude(base.hull, s.design.attitude);
    }
    s.kernel = eval::BuildDesignKernel(s.design);
    s.grid = opt::WaveFrequencyGrid(c, base.hydrostatics.L_m, base.water.g_m_s2);
    if (warnings && base.solver.rao.method == sk::RaoSolverOptions::Method::kTimeDomainStrip)
      for (const auto& w : sk::ValidityWarnings(s.design.speed_m_s, base.hydrostatics.L_m, base.water.g_m_s2,
                                                s.grid.omega_rad_s))
        warnings->push_back("case '" + c.label + "': " + w);
    speeds->push_back(std::move(s));
  }
  return [speeds](double Cs, int local) {
    const Speed& s = speeds->at(local);
    const sk::RaoTable rao = eval::DesignRaosFromKernel(s.design, s.kernel, s.grid.omega_rad_s, Cs);
    RaoPrediction p;
    for (int i : s.grid.index_of_point) {
      p.heave.push_back(rao.heave.at(i));
      p.pitch.push_back(rao.pitch.at(i));
    }
    return p;
  };
}

CsRaoModel CombineCsModels(std::vector<CsModelPart> parts) {
  int count = 0;
  for (const auto& part : parts)
    for (int c : part.cases) count = std::max(count, c + 1);
  auto route = std::make_shared<std::vector<std::pair<int, int>>>(count);  // global → (part, local)
  for (int p = 0; p < static_cast<int>(parts.size()); ++p)
    for (int l = 0; l < static_cast<int>(parts[p].cases.size()); ++l) (*route)[parts[p].cases[l]] = {p, l};
  auto shared = std::make_shared<std::vector<CsModelPart>>(std::move(parts));
  return [shared, route](double Cs, int case_index) {
    const auto [p, local] = route->at(case_index);
    return (*shared)[p].model(Cs, local);
  };
}

}  // namespace hullopt::calib
