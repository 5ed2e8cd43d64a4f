#pragma once
// A SWATH-like section with a re-entrant corner, for the section solvers' tests.
#include <array>
#include <cmath>
#include <vector>

namespace hullopt::testing {

// Half contour of a circular bulb (radius R, centre `depth` below the waterline) under a straight strut of
// half-width `strut`, keel to waterline; the junction is a sharp re-entrant corner (interior angle
// 180° + the angle between strut and circle, about 255° here).
inline std::vector<std::array<double, 2>> BulbUnderStrut(double R, double depth, double strut) {
  std::vector<std::array<double, 2>> c;
  const double end = M_PI - std::asin(strut / R);  // polar angle from the keel of the junction
  for (int i = 0; i <= 400; ++i) {
    const double t = end * i / 400;
    c.push_back({R * std::sin(t), -depth - R * std::cos(t)});
  }
  const double top = c.back()[1];
  for (int i = 1; i <= 40; ++i) c.push_back({strut, top * (1.0 - i / 40.0)});
  return c;
}

}  // namespace hullopt::testing
