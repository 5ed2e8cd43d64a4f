#pragma once
// The thin-ship description of a hull: each body's half-breadth f(x, depth) on its centre plane, sampled at
// the body's stations and at equally spaced depths below the waterline. Michell's integral works on this.
#include <vector>

#include "parametric_hull/hull_form.h"

namespace hullopt::res {

/// Half-breadth of one body on a grid: x at the body's wetted stations (aft to forward), depth d = T - z at
/// depth_points equally spaced values from 0 (waterline) to the deepest keel of the body.
struct CentrePlaneGrid {
  double y_centre_m = 0.0;      ///< [m] lateral position of the body's centre plane
  bool mirrored = false;        ///< true for one of a mirror pair at ±y_centre_m
  std::vector<double> x_m;      ///< [m] station positions, strictly increasing
  double depth_step_m = 0.0;    ///< [m] spacing of the depth nodes d_k = k · depth_step_m
  int depth_points = 0;         ///< number of depth nodes
  std::vector<double> f_m;      ///< [m] half-breadth f(x_i, d_k) at index i * depth_points + k (0 below the keel)
  /// [m] half-breadth at (x_i, d_k).
  double F(size_t i, int k) const { return f_m[i * depth_points + k]; }
};

/// Half-breadth [m] of the wetted contour of `station` at height z_m above the baseline: linear between the
/// contour points that bracket z (the last point at z for a horizontal run such as a flat bottom), 0 below the
/// keel, and the top point's y above the contour.
double HalfBreadthAt(const hull::Station& station, double z_m);

/// The centre-plane grids of all bodies of `hull` at its draught. Stations of a body that are dry are left
/// out. Throws std::invalid_argument if depth_points < 2 or a body has fewer than 2 wet stations.
std::vector<CentrePlaneGrid> SampleCentrePlanes(const hull::HullForm& hull, int depth_points);

}  // namespace hullopt::res
