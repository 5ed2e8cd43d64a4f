#include "resistance/centre_plane.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "parametric_hull/section_geometry.h"

namespace hullopt::res {

double HalfBreadthAt(const hull::Station& st, double z_m) {
  const auto& z = st.z_m;
  if (z.empty() || z_m < z.front()) return 0.0;
  const size_t j = std::upper_bound(z.begin(), z.end(), z_m) - z.begin();  // first point above z_m
  if (j == z.size()) return st.y_m.back();
  const double dz = z[j] - z[j - 1];
  const double f = dz > 0.0 ? (z_m - z[j - 1]) / dz : 0.0;
  return st.y_m[j - 1] + f * (st.y_m[j] - st.y_m[j - 1]);
}

std::vector<CentrePlaneGrid> SampleCentrePlanes(const hull::HullForm& hull, int depth_points) {
  if (depth_points < 2)
    throw std::invalid_argument("centre plane: depth_points = " + std::to_string(depth_points) + ": must be >= 2");
  const double T = hull.draught_m;
  std::vector<CentrePlaneGrid> grids;
  for (const auto& body : hull.bodies) {
    std::vector<const hull::Station*> wet;
    double deepest = 0.0;
    for (const auto& st : body.stations) {
      if (st.z_m.empty() || st.z_m.front() > T) continue;
      wet.push_back(&st);
      deepest = std::max(deepest, T - st.z_m.front());
    }
    if (wet.size() < 2)
      throw std::invalid_argument("centre plane: body '" + body.role + "' has fewer than 2 wet stations");
    CentrePlaneGrid g;
    g.y_centre_m = body.y_centre_m;
    g.mirrored = body.y_centre_m > 0.0;
    g.depth_points = depth_points;
    g.depth_step_m = deepest / (depth_points - 1);
    g.x_m.reserve(wet.size());
    g.f_m.assign(wet.size() * depth_points, 0.0);
    for (size_t i = 0; i < wet.size(); ++i) {
      g.x_m.push_back(wet[i]->x_m);
      for (int k = 0; k < depth_points; ++k)
        g.f_m[i * depth_points + k] = HalfBreadthAt(*wet[i], T - k * g.depth_step_m);
    }
    grids.push_back(std::move(g));
  }
  return grids;
}

}  // namespace hullopt::res
