#pragma once
// The Delft 372 tank RAOs at Fn 0.75 (data/delft372/delft372_tank_rao_fn075.csv) as the measured curve of an
// RAO figure, for the validation tests that plot against them.
#include <string>
#include <vector>

#include "io/report/rao_plot.h"
#include "io/formats/tank_rao_reader.h"

namespace hullopt::testing {

inline io::MeasuredRao MeasuredFromTank(const std::vector<opt::TankRaoPoint>& tank) {
  io::MeasuredRao m;
  m.label = "tank (van 't Veer 1998)";
  for (const auto& p : tank) {
    m.lambda_over_L.push_back(p.lambda_over_L);
    m.heave_amp.push_back(p.heave_amp);
    m.heave_phase_deg.push_back(p.heave_phase_deg);
    m.pitch_amp.push_back(p.pitch_amp);
    m.pitch_phase_deg.push_back(p.pitch_phase_deg);
  }
  return m;
}

inline std::vector<opt::TankRaoPoint> Delft372TankRao(const std::string& source_dir) {
  return io::ReadTankRaoCsv(source_dir + "/data/delft372/delft372_tank_rao_fn075.csv");
}

}  // namespace hullopt::testing
