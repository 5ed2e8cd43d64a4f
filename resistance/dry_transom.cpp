#include "resistance/dry_transom.h"

#include <algorithm>

#include "parametric_hull/section_geometry.h"

namespace hullopt::res {

TransomGeometry ComputeTransomGeometry(const hull::HullForm& hull) {
  TransomGeometry t;
  for (const auto& b : hull.bodies) {
    for (const auto& st : b.stations) {  // the first wet station is the transom
      const hull::SectionProperties p = hull::ComputeSectionProperties(st, hull.draught_m);
      if (!p.wet) continue;
      const double m = b.y_centre_m > 0.0 ? 2.0 : 1.0;
      // both sides of the body: 2 × half-section area and moment
      t.area_m2 += m * 2.0 * p.area_m2;
      t.first_moment_m3 += m * 2.0 * (hull.draught_m * p.area_m2 - p.moment_z_m3);
      if (p.area_m2 > 0.0) t.max_depth_m = std::max(t.max_depth_m, hull.draught_m - p.keel_z_m);
      break;
    }
  }
  return t;
}

}  // namespace hullopt::res
