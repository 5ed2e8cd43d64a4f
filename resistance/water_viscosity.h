#pragma once
// Kinematic viscosity of the water for the Reynolds number of the friction line.
namespace hullopt::res {

/// [m^2/s] fresh water at 15 °C, ITTC Recommended Procedure 7.5-02-01-03 (2011), "Fresh water and seawater
/// properties" (IAPWS-based).
constexpr double kFreshWater15CViscosity = 1.1386e-6;
/// [m^2/s] sea water at 15 °C and absolute salinity 35.16504 g/kg, same procedure.
constexpr double kSeaWater15CViscosity = 1.1892e-6;
/// [kg/m^3] densities at or above this count as sea water when the viscosity follows the density: halfway
/// between fresh (999.1) and sea water (1026.0) at 15 °C, so 1000 (a fresh-water tank) and 1025 (the default)
/// fall clearly on either side.
constexpr double kSaltWaterDensityThreshold = 1012.5;

/// The 15 °C viscosity of fresh or sea water chosen by the density rho_kg_m3 (see the threshold above).
double ViscosityForDensity(double rho_kg_m3);

}  // namespace hullopt::res
