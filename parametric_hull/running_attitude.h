#pragma once
// The steady running attitude of a hull at speed: the calm-water sinkage and trim under which the strips,
// the hydrostatics and the RAOs see the wetted hull.
//
// Sign convention (docs/hull-generator.md "Running attitude"): sinkage_m > 0 moves the hull DOWN at the pivot
// (deeper); trim > 0 is BOW UP (trim by the stern: the stern deeper, the bow higher). Tank data with sinkage
// "+ up" and trim "− = bow up" (Delft 372) convert as sinkage_m = −rise, trim_deg = −trim_tank_deg.
//
// The hull stays in its own axes and the waterline stays at z = draught_m: every station is moved vertically by
// the hull's displacement at its x, Δz(x) = −sinkage + (x − pivot)·tan(trim), so a station sees the draught
// T_local(x) = T + sinkage − (x − pivot)·tan(trim). This is the rigid rotation to first order in the trim
// angle (stations stay vertical; the length of a station's contour and its x are unchanged): the relative
// error in local draught is 1 − cos(trim), below 0.4% for |trim| ≤ kMaxTrimDeg.
#include "parametric_hull/hull_form.h"

namespace hullopt::hull {

/// [deg] largest |trim| accepted: beyond it the vertical-shear model (above) departs from a rigid rotation by
/// more than 1 − cos(5°) = 0.4% of the local draught.
constexpr double kMaxTrimDeg = 5.0;
/// Fraction of the at-rest wetted length of a body, from its forward end, where stations may lift clear of the
/// water at the running attitude (a fast hull's forefoot rising out of the water). A station aft of it that is
/// wet at rest and dry at the attitude — the transom or the run lifting out — is refused.
constexpr double kBowEmergenceFraction = 0.25;

struct RunningAttitude {
  double sinkage_m = 0.0;  ///< [m] vertical displacement of the hull at the pivot, + down (deeper)
  double trim_deg = 0.0;   ///< [deg] trim angle, + bow up
  double pivot_x_m = 0.0;  ///< [m from AP] where sinkage is given (the centre of gravity)
  bool IsEvenKeel() const { return sinkage_m == 0.0 && trim_deg == 0.0; }
};

/// The hull at the running attitude (see above). Even keel returns the hull unchanged (bitwise). Throws
/// std::invalid_argument for non-finite values or |trim| > kMaxTrimDeg, and std::domain_error naming the body
/// and x if the attitude submerges a deck edge (a station whose contour ends at or below the waterline) or
/// lifts out of the water a station that is wet at rest outside the forward kBowEmergenceFraction of the
/// body's wetted length (or every station of a body).
HullForm ApplyRunningAttitude(const HullForm& at_rest, const RunningAttitude& attitude);

}  // namespace hullopt::hull
