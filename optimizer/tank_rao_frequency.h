#pragma once
// Frequencies of measured tank points for a ship of length L at the point's Froude number, head seas, deep
// water: from λ/L (k = 2π/(λ/L·L), ω = sqrt(gk)) or from ω_e (ω_e = ω + ω²U/g, U = Fn·sqrt(gL)). A point with
// both uses ω_e. Also the increasing, duplicate-free wave-frequency grid a strip solver wants for one case.
#include <vector>

#include "optimizer/tank_rao_data.h"

namespace hullopt::opt {

/// Wave frequency ω [rad/s] of a measured point. length_m [m] > 0, g_m_s2 [m/s²] > 0.
double PointWaveFrequency(const TankRaoPoint& p, double length_m, double g_m_s2);
/// Encounter frequency ω_e [rad/s] of a measured point.
double PointEncounterFrequency(const TankRaoPoint& p, double length_m, double g_m_s2);

/// The case's wave frequencies, increasing and without duplicates (for solvers that want such a list), and
/// for every point of the case the index of its frequency in that list.
struct CaseFrequencyGrid {
  std::vector<double> omega_rad_s;  ///< [rad/s] increasing, distinct
  std::vector<int> index_of_point;  ///< per CalibrationCase::points entry
};
CaseFrequencyGrid WaveFrequencyGrid(const CalibrationCase& c, double length_m, double g_m_s2);

}  // namespace hullopt::opt
