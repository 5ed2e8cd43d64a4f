#include "evaluation/water.h"

namespace hullopt::eval {

bool WaterOptions::IsValid(std::string* error) const {
  if (!(rho_kg_m3 >= 500.0 && rho_kg_m3 <= 2000.0)) {
    if (error) *error = "rho_kg_m3 = " + std::to_string(rho_kg_m3) + ": must lie in [500, 2000] kg/m^3";
    return false;
  }
  if (!(g_m_s2 > 0.0 && g_m_s2 < 100.0)) {
    if (error) *error = "g_m_s2 = " + std::to_string(g_m_s2) + ": must lie in (0, 100) m/s^2";
    return false;
  }
  return true;
}

}  // namespace hullopt::eval
