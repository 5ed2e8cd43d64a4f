#pragma once
// The water a design floats in.
#include <string>

namespace hullopt::eval {

struct WaterOptions {
  double rho_kg_m3 = 1025.0;  ///< [kg/m^3] sea water by default; 1000 for fresh-water tank data
  double g_m_s2 = 9.81;       ///< [m/s^2]
  bool IsValid(std::string* error) const;
};

}  // namespace hullopt::eval
