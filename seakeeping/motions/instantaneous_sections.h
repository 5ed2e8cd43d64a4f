#pragma once
// What the paths on the instantaneous hull (forced oscillation, calm water) need of a hull besides its strip
// panels: the stations of the strip grid and the immersed area and water-line beam of the sections at a
// station cut at any water line.
#include <vector>

#include "parametric_hull/hull_form.h"
#include "seakeeping/strip/strip_geometry.h"

namespace hullopt::sk {

/// The strip grid of StripKernelGeometry with stations at the cell faces: x_m from the foremost to the aftmost
/// station of all bodies (bow first), with the station weights. Throws std::invalid_argument for a hull with
/// no length.
struct CellFaceStations {
  std::vector<double> x_m, weight_m;
  double dx_m = 0.0;
};
CellFaceStations CellFaceGrid(const hull::HullForm& hull, int sections);

/// Immersed area [m²] and water-line beam [m] of the bodies `geometry.body` selects at x [m from AP], cut at
/// z = draught_m above the baseline (mirror pairs counted twice).
struct SectionSums {
  double beam_m = 0.0, area_m2 = 0.0;
};
SectionSums WetSectionSums(const hull::HullForm& hull, double x_m, double draught_m,
                           const StripGeometryOptions& geometry);

}  // namespace hullopt::sk
