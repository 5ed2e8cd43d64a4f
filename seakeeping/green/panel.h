#pragma once
// Straight boundary-element panels in the strip plane (y, z), free surface z = 0, fluid in z < 0.
// A body contour is panelled from the port waterline down round the keel to the starboard waterline; with that
// order the normal (−dz, dy)/|d| of the direction d = p2 − p1 points INTO THE FLUID (out of the body).
#include <array>
#include <cmath>
#include <vector>

namespace hullopt::sk {

struct Panel {
  double y1 = 0, z1 = 0;  ///< [m] start point
  double y2 = 0, z2 = 0;  ///< [m] end point
  double Length() const { return std::hypot(y2 - y1, z2 - z1); }
  double MidY() const { return 0.5 * (y1 + y2); }
  double MidZ() const { return 0.5 * (z1 + z2); }
  /// Unit normal into the fluid, (ny, nz).
  std::array<double, 2> Normal() const {
    const double l = Length();
    return {-(z2 - z1) / l, (y2 - y1) / l};
  }
};

/// Panels a symmetric section from its half contour. half_contour: points (y >= 0, z <= 0 relative to the free
/// surface) from the keel on the centreline (y = 0) up to the waterline (z = 0). The section is mirrored about
/// y = 0 and shifted to y_centre. n_panels (even, >= 4) panels over the whole wetted girth, spaced by arc length
/// with cosine clustering towards the waterline ends (where the memory kernel varies fastest, theory notes
/// §1.5), ordered port waterline → keel → starboard waterline. Throws std::invalid_argument for a contour that
/// does not start on the centreline, does not end at z = 0, or has fewer than 2 points.
std::vector<Panel> PanelSymmetricSection(const std::vector<std::array<double, 2>>& half_contour, int n_panels,
                                         double y_centre_m = 0.0);

}  // namespace hullopt::sk
