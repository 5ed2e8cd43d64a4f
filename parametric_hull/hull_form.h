#pragma once
// The geometric description of a hull that every other module consumes: transverse stations of one or more
// demihulls, each symmetric about its own centreline plane. Produced by the parametric generator or by the
// offsets/STL readers; consumed by hydrostatics, the strip model and the plots.
//
// Axes (docs/conventions.md): x forward from the aft perpendicular (AP), y to port, z up from the baseline.
#include <string>
#include <vector>

namespace hullopt::hull {

/// One transverse station of one demihull: the half-section contour on the port side of the demihull's own
/// centreline, as a polyline from the keel (y = 0) up to the deck edge. y may rise and fall (SWATH bulb),
/// z is non-decreasing along the contour.
struct Station {
  double x_m = 0.0;         ///< [m] longitudinal position from AP, positive forward
  std::vector<double> y_m;  ///< [m] half-breadth from the demihull centreline, >= 0
  std::vector<double> z_m;  ///< [m] height above the baseline
};

/// A hull body symmetric about its own centreline plane at y = y_centre_m. If y_centre_m > 0 the body is one
/// of a mirror pair at ±y_centre_m (catamaran/SWATH demihulls, trimaran outriggers); if 0 it sits on the ship
/// centreline (monohull, trimaran main hull).
struct Demihull {
  std::string role;               ///< "main", "demihull", "outrigger": for reports and plots
  double y_centre_m = 0.0;        ///< [m] lateral position of its centreline
  std::vector<Station> stations;  ///< ordered aft to forward (increasing x_m)
};

/// A complete hull at its design draught.
struct HullForm {
  std::string type;              ///< monohull | catamaran | swath | trihull | offsets
  std::vector<Demihull> bodies;  ///< first body is the main hull / the demihull
  double draught_m = 0.0;        ///< [m] design waterline height above the baseline
  double length_m = 0.0;         ///< [m] waterline length L of the main body, AP to FP
  /// What the generator changed from the requested design variables to build this hull, one line each
  /// ("LCF_pct_L -12.5 -> -6.25 (+6.25 % L): ..."); empty for a hull built as asked. Every output shows them.
  std::vector<std::string> adjustments;
  /// Number of physical bodies counting mirror pairs twice (1 monohull, 2 catamaran, 3 trihull).
  int BodyCount() const {
    int n = 0;
    for (const auto& b : bodies) n += b.y_centre_m > 0.0 ? 2 : 1;
    return n;
  }
};

/// Mass properties for the equations of motion. Defaults are filled in by the caller from hydrostatics.
struct MassProperties {
  double mass_kg = 0.0;        ///< [kg] whole vessel
  double lcg_m_from_ap = 0.0;  ///< [m] longitudinal centre of gravity from AP
  double kyy_m = 0.0;          ///< [m] pitch radius of gyration about the CG
  double kg_m = 0.0;           ///< [m] vertical centre of gravity above baseline
};

}  // namespace hullopt::hull
