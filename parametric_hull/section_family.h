#pragma once
// Section shapes that honour a local waterline half-breadth, draught and area exactly (in the polyline's own
// area, the measure the hydrostatics use). Each returns a Station contour from the keel up to the deck edge.
// Requests a family cannot meet throw std::domain_error naming the station, the family and the rule.
#include "parametric_hull/hull_form.h"

namespace hullopt::hull {

/// Common inputs of one section. Heights are above the baseline.
struct SectionTarget {
  double x_m = 0.0;               ///< [m] station position (for messages and the Station)
  double half_beam_m = 0.0;       ///< [m] half-breadth at the waterline (strut half-thickness for SWATH)
  double draught_m = 0.0;         ///< [m] local draught d: the keel is at waterline_z_m - d
  double area_m2 = 0.0;           ///< [m^2] full section area (both sides) below the waterline
  double waterline_z_m = 0.0;     ///< [m] T
  double deck_z_m = 0.0;          ///< [m] deck edge height (> T)
  double deck_half_beam_m = 0.0;  ///< [m] half-breadth at the deck edge (flare above the waterline)
  int points = 25;                ///< contour points below the waterline
};

/// Round bilge: superellipse |y/(b/2)|^n + |(T - z)/d|^n = 1 below the waterline, n found so that the
/// polyline area equals the target (area coefficient σ = A/(b d) from 0.15, hollow V, through π/4, elliptic,
/// to 0.98, nearly rectangular). A zero-area section is the stem line (b = 0) or a flat bottom at the
/// waterline (d = 0).
Station RoundBilgeSection(const SectionTarget& t);

/// Hard chine: straight deadrise from the keel to a chine at the full half-breadth, wall-sided above it; the
/// chine height 2 d (1 - σ) gives the area exactly. σ from 0.5 (chine at the waterline) to 1 (flat bottom).
Station HardChineSection(const SectionTarget& t);

/// SWATH: a submerged superelliptic bulb of half-width bulb_half_width_m and height bulb_height_m sitting on
/// the keel (z = waterline_z_m - draught_m), joined to a strut of half-thickness t.half_beam_m that rises
/// wall-sided through the waterline to the deck. If the strut is as wide as the bulb, the bulb's upper half
/// is replaced by the strut. t.area_m2 is ignored (the caller solves bulb size for area with SectionArea()).
/// bulb_exponent_lower shapes the bulb's lower half (its bottom; a large exponent gives a flat bottom with a
/// tight bilge, the chined run of a SWATH), bulb_exponent its upper half (and the lower half when
/// bulb_exponent_lower is 0).
Station SwathSection(const SectionTarget& t, double bulb_half_width_m, double bulb_height_m,
                     double bulb_exponent, double bulb_exponent_lower = 0.0);

/// Full (both sides) area below waterline_z_m of a contour, the same polyline rule as the hydrostatics.
double SectionArea(const Station& s, double waterline_z_m);

}  // namespace hullopt::hull
