#include "seas/passenger_positions.h"

#include <cmath>
#include <sstream>

namespace hullopt::sk {

bool HullExtent::IsValid(std::string* error) const {
  if (!(cg_to_transom_m > 0.0) || !(cg_to_bow_m > 0.0) || !std::isfinite(cg_to_transom_m) ||
      !std::isfinite(cg_to_bow_m)) {
    if (error) {
      std::ostringstream o;
      o << "hull extent: CG-to-transom " << cg_to_transom_m << " m and CG-to-bow " << cg_to_bow_m
        << " m must both be > 0 (the CG must lie on the hull)";
      *error = o.str();
    }
    return false;
  }
  return true;
}

std::vector<PassengerPosition> StandardPassengerPositions(double d) {
  return {{"forward", kForwardPositionFraction * d}, {"lcg", 0.0}, {"transom", -d}};
}

bool IsValidPassengerPosition(const PassengerPosition& p, const HullExtent& hull, std::string* error) {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (p.name.empty()) return fail("passenger position: name must not be empty");
  if (p.name == "forward" || p.name == "lcg" || p.name == "transom" || p.name == "mean")
    return fail("passenger position '" + p.name + "': name is reserved (forward, lcg, transom, mean)");
  if (!std::isfinite(p.x_from_cg_m) || p.x_from_cg_m < -hull.cg_to_transom_m ||
      p.x_from_cg_m > hull.cg_to_bow_m) {
    std::ostringstream o;
    o << "passenger position '" << p.name << "': x_from_cg_m = " << p.x_from_cg_m
      << " is outside the hull, which spans " << -hull.cg_to_transom_m << " (transom) to " << hull.cg_to_bow_m
      << " (bow) m from the CG";
    return fail(o.str());
  }
  return true;
}

}  // namespace hullopt::sk
