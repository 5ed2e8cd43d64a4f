#include "seakeeping/motions/instantaneous_sections.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "parametric_hull/section_geometry.h"
#include "seakeeping/strip/strip_kernel.h"

namespace hullopt::sk {

CellFaceStations CellFaceGrid(const hull::HullForm& hull, int sections) {
  double x_aft = std::numeric_limits<double>::infinity(), x_fwd = -x_aft;
  for (const auto& b : hull.bodies)
    if (!b.stations.empty())
      x_aft = std::min(x_aft, b.stations.front().x_m), x_fwd = std::max(x_fwd, b.stations.back().x_m);
  if (!(x_fwd > x_aft)) throw std::invalid_argument("the hull has no length (no stations)");
  CellFaceStations g;
  const int steps = sections + 1;
  g.dx_m = (x_fwd - x_aft) / sections;
  g.x_m.resize(steps), g.weight_m.resize(steps);
  for (int n = 0; n < steps; ++n) {
    g.x_m[n] = n == sections ? x_aft : x_fwd - n * g.dx_m;
    g.weight_m[n] = StationWeight(StationLayout::kCellFaces, n, steps, g.dx_m);
  }
  return g;
}

SectionSums WetSectionSums(const hull::HullForm& hull, double x_m, double draught_m,
                           const StripGeometryOptions& geometry) {
  SectionSums s;
  for (std::size_t b = 0; b < hull.bodies.size(); ++b) {
    if (geometry.body >= 0 && geometry.body != static_cast<int>(b)) continue;
    const auto& body = hull.bodies[b];
    const hull::Station st = hull::InterpolateStation(body, x_m);
    if (st.y_m.size() < 2) continue;
    const auto p = hull::ComputeSectionProperties(st, draught_m);
    if (!p.wet) continue;
    const double copies = (geometry.body < 0 && body.y_centre_m > 0.0) ? 2.0 : 1.0;
    s.beam_m += copies * 2.0 * p.waterline_half_breadth_m;
    s.area_m2 += copies * 2.0 * p.area_m2;
  }
  return s;
}

}  // namespace hullopt::sk
