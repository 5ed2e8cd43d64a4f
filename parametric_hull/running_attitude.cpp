#include "parametric_hull/running_attitude.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <algorithm>

namespace hullopt::hull {
namespace {

// A station is wet when its keel is below the waterline (as section_geometry.h's WettedContour).
bool IsWet(const Station& s, double draught_m) { return !s.z_m.empty() && s.z_m.front() < draught_m; }

std::string Describe(const RunningAttitude& a) {
  std::ostringstream os;
  os << "running attitude sinkage " << a.sinkage_m << " m (+ down) and trim " << a.trim_deg
     << " deg (+ bow up) about x = " << a.pivot_x_m << " m";
  return os.str();
}

}  // namespace

HullForm ApplyRunningAttitude(const HullForm& at_rest, const RunningAttitude& a) {
  if (!std::isfinite(a.sinkage_m) || !std::isfinite(a.trim_deg) || !std::isfinite(a.pivot_x_m))
    throw std::invalid_argument("running attitude: sinkage, trim and pivot must be finite");
  if (std::fabs(a.trim_deg) > kMaxTrimDeg) {
    std::ostringstream os;
    os << "running attitude: trim " << a.trim_deg << " deg: |trim| must be <= " << kMaxTrimDeg
       << " deg (stations are kept vertical, a small-angle model)";
    throw std::invalid_argument(os.str());
  }
  if (a.IsEvenKeel()) return at_rest;
  const double T = at_rest.draught_m;
  const double slope = std::tan(a.trim_deg * M_PI / 180.0);
  HullForm out = at_rest;
  for (std::size_t b = 0; b < out.bodies.size(); ++b) {
    Demihull& body = out.bodies[b];
    // The body's wetted length at rest, for the bow emergence allowance.
    double x_wet_aft = INFINITY, x_wet_fwd = -INFINITY;
    for (const Station& s : at_rest.bodies[b].stations)
      if (IsWet(s, T)) {
        x_wet_aft = std::min(x_wet_aft, s.x_m);
        x_wet_fwd = std::max(x_wet_fwd, s.x_m);
      }
    const double x_bow_zone = x_wet_fwd - kBowEmergenceFraction * (x_wet_fwd - x_wet_aft);
    bool any_wet = false;
    for (Station& s : body.stations) {
      const bool wet_at_rest = IsWet(s, T);
      const double dz = -a.sinkage_m + (s.x_m - a.pivot_x_m) * slope;
      for (double& z : s.z_m) z += dz;
      if (s.z_m.empty()) continue;
      std::ostringstream os;
      os << "body '" << body.role << "' station x = " << s.x_m << " m: ";
      if (s.z_m.back() <= T) {
        os << "the deck edge is " << T - s.z_m.back() << " m below the waterline at the " << Describe(a)
           << " (rule: the deck must stay above water)";
        throw std::domain_error(os.str());
      }
      const bool wet = IsWet(s, T);
      any_wet = any_wet || wet;
      if (wet_at_rest && !wet && s.x_m < x_bow_zone) {
        os << "wet at rest, lifted out of the water (keel " << s.z_m.front() - T << " m above it) by the "
           << Describe(a) << " (rule: only stations in the forward " << kBowEmergenceFraction * 100
           << "% of the wetted length, from x = " << x_bow_zone << " m, may emerge)";
        throw std::domain_error(os.str());
      }
    }
    if (!any_wet && std::isfinite(x_wet_aft))
      throw std::domain_error("body '" + body.role + "': every station is out of the water at the " +
                              Describe(a));
  }
  return out;
}

}  // namespace hullopt::hull
