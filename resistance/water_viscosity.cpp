#include "resistance/water_viscosity.h"

namespace hullopt::res {

double ViscosityForDensity(double rho_kg_m3) {
  return rho_kg_m3 >= kSaltWaterDensityThreshold ? kSeaWater15CViscosity : kFreshWater15CViscosity;
}

}  // namespace hullopt::res
