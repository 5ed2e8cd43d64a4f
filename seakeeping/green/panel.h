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
  /// [rad] Turning of the smooth contour this chord stands for, between its end points (κ·L for a circular
  /// arc; positive where the body is convex, 0 for a straight piece or a contour given only by its corners).
  /// It enters the panel's own normal velocity (rankine_panel.h).
  double turn_rad = 0;
  double Length() const { return std::hypot(y2 - y1, z2 - z1); }
  double MidY() const { return 0.5 * (y1 + y2); }
  double MidZ() const { return 0.5 * (z1 + z2); }
  /// Unit normal into the fluid, (ny, nz).
  std::array<double, 2> Normal() const {
    const double l = Length();
    return {-(z2 - z1) / l, (y2 - y1) / l};
  }
};

/// How PanelSymmetricSection spreads a given number of panels over the girth. Each panel end point is placed
/// so that the panels share equally in ∫ ds/h(s), h the target spacing: the smallest of the uniform spacing,
/// the spacing that turns by max_turn_rad (curvature), thickness_fraction × the local thickness (thin struts
/// and plates: panels of opposite faces closer than a panel length make the source system near-singular) and
/// end_spacing × uniform + grading × distance to the nearest corner or to the waterline. Vertices of the
/// contour that turn by more than corner_angle_rad are panel end points. Folds thinner than
/// cut_thickness_fraction × the uniform spacing are replaced by the chord across their root.
struct PanelSpacing {
  double corner_angle_rad = M_PI / 6;  ///< [rad] a sharper vertex is a corner (chine, box bilge)
  double max_turn_rad = 0.35;          ///< [rad] turning of the contour per panel where it is curved
  double thickness_fraction = 1.0;     ///< panel length / local thickness
  double fold_ratio = 3.0;  ///< a contour point this many times farther along the contour than in space lies across a thin part
  double end_spacing = 0.25;  ///< spacing at corners and the waterline, as a fraction of the uniform one
  double grading = 0.5;       ///< growth of the spacing with the distance from a corner or the waterline
  /// A fold (fin, plate edge) thinner than this fraction of the uniform spacing is cut off at its root: the
  /// given number of panels cannot resolve it, and panels on its two faces would make the source system
  /// near-singular (condition ∝ panel length / thickness). 0: never cut.
  double cut_thickness_fraction = 0.1;
};

/// Panels a symmetric section from its half contour. half_contour: points (y >= 0, z <= 0 relative to the free
/// surface) from the keel on the centreline (y = 0) up to the waterline (z = 0); a dense polyline stands for a
/// smooth contour, its sharp vertices for corners. The section is mirrored about y = 0 and shifted to
/// y_centre. n_panels (even, >= 4) panels over the whole wetted girth, spaced as `spacing` says, ordered port
/// waterline → keel → starboard waterline; each carries the turning of the contour between its end points
/// (Panel::turn_rad). Throws std::invalid_argument for a contour that does not start on the centreline, does
/// not end at z = 0, or has fewer than 2 points.
std::vector<Panel> PanelSymmetricSection(const std::vector<std::array<double, 2>>& half_contour, int n_panels,
                                         double y_centre_m = 0.0, const PanelSpacing& spacing = {});

}  // namespace hullopt::sk
