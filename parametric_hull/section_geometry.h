#pragma once
// Geometry of stations that the hydrostatics, the strip solver and the readers share: a section at any x,
// the wetted part of a section, per-section integrals, resampling of a hull to equally spaced stations and
// the longitudinal quadrature rule. Everything here is the ONE definition of these quantities in hullopt: the
// generator scales to its displacement with the same rules, so targets are met in the code's own measure.
#include <array>
#include <vector>

#include "parametric_hull/hull_form.h"

namespace hullopt::hull {

/// The section of a demihull at longitudinal position x_m [m from AP], between its stations.
/// The two neighbouring contours are parametrised by normalised arc length (keel = 0, deck edge = 1); the
/// breakpoints of both are merged, so at a station the station's own polyline is returned exactly (plus
/// collinear points) and chines stay sharp where both neighbours have them at similar arc length. Points are
/// then blended linearly in x. z stays non-decreasing because both contours are.
/// Outside [first station x, last station x] the body does not exist: the result has no points (dry).
/// Throws std::invalid_argument if the demihull has no stations.
Station InterpolateStation(const Demihull& body, double x_m);

/// The wetted part of a station at draught draught_m [m above baseline]: the contour from the keel up to the
/// first crossing of the waterline z = draught_m (the crossing point included), as (y, z) pairs in [m] with z
/// from the baseline. Points exactly on the waterline are kept (a flat transom bottom at z = T gives a
/// zero-area contour with its waterline breadth). Empty if the keel is above the waterline (dry station).
/// If the whole contour is below the waterline it is returned whole (deck edge submerged).
std::vector<std::array<double, 2>> WettedContour(const Station& station, double draught_m);

/// Integrals of one half-section (one side of the demihull centreline) below the waterline.
struct SectionProperties {
  double area_m2 = 0.0;      ///< [m^2] half-section area below the waterline
  double moment_z_m3 = 0.0;  ///< [m^3] first moment of that area about the baseline (z from baseline)
  double waterline_half_breadth_m = 0.0;  ///< [m] y at the waterline crossing (0 if dry)
  double max_half_breadth_m = 0.0;        ///< [m] largest y below the waterline
  double girth_m = 0.0;                   ///< [m] wetted girth of the half contour (keel to waterline)
  double keel_z_m = 0.0;                  ///< [m] lowest z of the contour
  bool wet = false;                       ///< false if the station is dry at this draught
};

/// Section integrals from the wetted polyline (exact for the polyline; z must be non-decreasing).
SectionProperties ComputeSectionProperties(const Station& station, double draught_m);

/// Weights w_i with sum_i w_i f(x_i) ≈ ∫ f dx over [x_0, x_{n-1}], for strictly increasing, possibly unevenly
/// spaced x: composite Simpson over pairs of intervals (exact for quadratics on each pair), the last interval
/// of an odd count by the quadratic through its last three points; trapezoid for two points, zero for one.
/// Throws std::invalid_argument if x is not strictly increasing.
std::vector<double> LongitudinalWeights(const std::vector<double>& x_m);

/// The hull with every body resampled to `stations` equally spaced stations over the waterline length of the
/// main body (bodies[0]): x from its first to its last station, which for generated hulls are AP and FP.
/// Other bodies (outriggers, second demihull) get the stations of that grid that lie within their own range,
/// plus their own end stations if these are not on the grid, so their ends are not lost.
/// Throws std::invalid_argument if stations < 2 or the hull has no body with stations.
HullForm Resample(const HullForm& hull, int stations);

}  // namespace hullopt::hull
