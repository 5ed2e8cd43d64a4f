#include "optimizer/tank_rao_frequency.h"

#include <algorithm>
#include <cmath>

#include "seakeeping/motions/encounter_frequency.h"

namespace hullopt::opt {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

double PointWaveFrequency(const TankRaoPoint& p, double length_m, double g_m_s2) {
  const double U = p.Fn * std::sqrt(g_m_s2 * length_m);
  if (p.has_omega_e) return sk::HeadSeaWaveFrequency(p.omega_e_rad_s, U, g_m_s2);
  return std::sqrt(g_m_s2 * 2.0 * kPi / (p.lambda_over_L * length_m));
}

double PointEncounterFrequency(const TankRaoPoint& p, double length_m, double g_m_s2) {
  if (p.has_omega_e) return p.omega_e_rad_s;
  const double U = p.Fn * std::sqrt(g_m_s2 * length_m);
  return sk::HeadSeaEncounterFrequency(PointWaveFrequency(p, length_m, g_m_s2), U, g_m_s2);
}

CaseFrequencyGrid WaveFrequencyGrid(const CalibrationCase& c, double length_m, double g_m_s2) {
  CaseFrequencyGrid grid;
  std::vector<double> w;
  for (const auto& p : c.points) w.push_back(PointWaveFrequency(p, length_m, g_m_s2));
  grid.omega_rad_s = w;
  std::sort(grid.omega_rad_s.begin(), grid.omega_rad_s.end());
  grid.omega_rad_s.erase(std::unique(grid.omega_rad_s.begin(), grid.omega_rad_s.end()),
                         grid.omega_rad_s.end());
  for (double v : w) {
    grid.index_of_point.push_back(static_cast<int>(
        std::lower_bound(grid.omega_rad_s.begin(), grid.omega_rad_s.end(), v) - grid.omega_rad_s.begin()));
  }
  return grid;
}

}  // namespace hullopt::opt
