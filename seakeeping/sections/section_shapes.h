#pragma once
// Half contours of standard 2D sections for verification and `hullopt section`: points (y >= 0, z <= 0 from the
// free surface) from the keel on the centreline up to the waterline, ready for PanelSymmetricSection.
#include <array>
#include <vector>

namespace hullopt::sk {

using HalfContour = std::vector<std::array<double, 2>>;

/// Semicircle of radius R [m] (a circular cylinder floating at its centre line).
HalfContour SemicircleContour(double radius_m, int points = 400);
/// Rectangle of beam B and draught T [m].
HalfContour RectangleContour(double beam_m, double draught_m);
/// Lewis form of beam B, draught T and area coefficient σ = A/(BT) (docs/sections.md, 'Lewis forms':
/// Journée's inverse).
/// Throws std::domain_error naming B/T and σ when no non-re-entrant Lewis form exists.
HalfContour LewisContour(double beam_m, double draught_m, double area_coefficient, int points = 400);

}  // namespace hullopt::sk
