#pragma once
// Passenger positions along the centreline, x [m] forward of the CG (docs/conventions.md; Davis & Holloway
// 2003): "lcg" at the CG, "transom" at the transom, "forward" 60 % of the LCG-to-transom distance forward of
// the LCG. The design's average MSI is the mean over these three. Users may add named points anywhere on the
// hull.
#include <string>
#include <vector>

namespace hullopt::sk {

struct PassengerPosition {
  std::string name;          ///< "forward", "lcg", "transom" or a user name
  double x_from_cg_m = 0.0;  ///< [m] forward of the CG (negative aft)
};

/// Longitudinal extent of the hull about the CG (options struct).
struct HullExtent {
  double cg_to_transom_m = 0.0;  ///< [m] distance from the CG aft to the transom (> 0)
  double cg_to_bow_m = 0.0;      ///< [m] distance from the CG forward to the bow (> 0)
  bool IsValid(std::string* error) const;
};

/// Forward share of the LCG-to-transom distance (the paper's 60 %).
constexpr double kForwardPositionFraction = 0.6;

/// forward (+0.6 d), lcg (0), transom (−d), in this order, d = cg_to_transom_m.
std::vector<PassengerPosition> StandardPassengerPositions(double cg_to_transom_m);

/// A user point must have a non-empty name other than the standard names and "mean", and lie on the hull:
/// −cg_to_transom ≤ x ≤ cg_to_bow. The error names the point, its x and the hull limits.
bool IsValidPassengerPosition(const PassengerPosition& p, const HullExtent& hull, std::string* error);

}  // namespace hullopt::sk
