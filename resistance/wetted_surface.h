#pragma once
// Wetted surface of a hull from its stations, including the longitudinal slope of the surface (which the
// girth integral of the hydrostatics leaves out).
#include "parametric_hull/hull_form.h"

namespace hullopt::res {

/// [m^2] wetted surface of one body (both sides of its own centreline, NOT doubled for a mirror pair) at
/// draught_m. Between neighbouring stations the surface is the hull's own ruled surface: points of equal
/// normalised arc length of the two full contours joined by straight lines (as hull::InterpolateStation
/// blends them), at both contours' breakpoints plus `points` even fractions; each strip is split into two
/// triangles clipped to z <= draught_m. Exact for surfaces made of planes (boxes, wall-sided tapers). A dry
/// transom face is not wetted surface.
double BodyWettedSurface(const hull::Demihull& body, double draught_m, int points = 64);

/// [m^2] wetted surface of the whole hull (mirror pairs counted twice).
double WettedSurface(const hull::HullForm& hull, int points = 64);

}  // namespace hullopt::res
