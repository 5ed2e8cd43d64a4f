#pragma once
// The Wigley hull of data/peers-oblique/ (L 3 m, B 0.3 m, T 0.1875 m) as oblique-strip-theory stations, and
// its mass properties there, for the oblique-sea tests.
#include <algorithm>
#include <cmath>
#include <vector>

#include "seakeeping/motions/oblique_strip_theory.h"
#include "seakeeping/strip/strip_geometry.h"
#include "support/wigley_hull.h"

namespace hullopt::test {

constexpr double kWigleyL = 3.0, kWigleyB = 0.3, kWigleyT = 0.1875;

/// `sections` stations at the cell midpoints of the hull's length (weight L/sections each), panelled with
/// `panels` panels per section by the strip solvers' own route (sk::ObliqueStripStations). x from the aft
/// perpendicular, so midships is x = L/2.
inline std::vector<sk::ObliqueStripStation> WigleyObliqueStations(int sections, int panels) {
  sk::StripGeometryOptions o;
  o.sections = sections;
  o.panels = panels;
  o.layout = sk::StationLayout::kCellMidpoints;
  return sk::ObliqueStripStations(WigleyHull(kWigleyL, kWigleyB, kWigleyT, 201, 61), o);
}

/// The data's mass: 75 kg (the displaced mass at ρ = 1000), CG at midships, z_G = KG − T; I44 = m (0.35 B)²,
/// I55 = I66 = m (0.25 L)² (data/peers-oblique/SOURCE.md).
inline sk::ObliqueMassProperties WigleyObliqueMass(double kg_m) {
  sk::ObliqueMassProperties m;
  m.mass_kg = 75.0;
  m.x_g_m = 0.5 * kWigleyL;
  m.z_g_m = kg_m - kWigleyT;
  m.inertia_kg_m2.diagonal() << 75.0 * std::pow(0.35 * kWigleyB, 2), 75.0 * std::pow(0.25 * kWigleyL, 2),
      75.0 * std::pow(0.25 * kWigleyL, 2);
  return m;
}

/// The same hull at `scale` times its size (Froude similar; ρ = 1000 as the data): stations as above, and the
/// mass with every length scaled, for evaluations in ship-scale seas (MSI needs ship-scale periods).
inline std::vector<sk::ObliqueStripStation> WigleyShipStations(double scale, int sections, int panels) {
  sk::StripGeometryOptions o;
  o.sections = sections;
  o.panels = panels;
  o.layout = sk::StationLayout::kCellMidpoints;
  return sk::ObliqueStripStations(
      WigleyHull(scale * kWigleyL, scale * kWigleyB, scale * kWigleyT, 201, 61), o);
}
inline sk::ObliqueMassProperties WigleyShipMass(double scale, double kg_m) {
  sk::ObliqueMassProperties m = WigleyObliqueMass(kg_m / scale);
  m.mass_kg *= scale * scale * scale;
  m.x_g_m *= scale;
  m.z_g_m *= scale;
  m.inertia_kg_m2 *= scale * scale * scale * scale * scale;
  return m;
}

/// Solver options of the data (fresh water, ρ = 1000; g = 9.81) at speed_m_s.
inline sk::ObliqueStripOptions WigleyObliqueOptions(double speed_m_s) {
  sk::ObliqueStripOptions o;
  o.rho_kg_m3 = 1000.0;
  o.g_m_s2 = 9.81;
  o.speed_m_s = speed_m_s;
  return o;
}

/// The largest of |F_d|/|F_3| and |X_d|/(|X_3| + |X_5|) over sway, roll and yaw (d = 2, 4, 6): zero to
/// rounding for a port–starboard symmetric hull in head or following seas.
inline double AntisymmetricFraction(const sk::ObliqueWaveResult& w) {
  const double scale = std::abs(w.excitation[2]), rao_scale = std::abs(w.rao[2]) + std::abs(w.rao[4]);
  double out = 0.0;
  for (int d : {1, 3, 5})
    out = std::max({out, std::abs(w.excitation[d]) / scale, std::abs(w.rao[d]) / rao_scale});
  return out;
}

}  // namespace hullopt::test
