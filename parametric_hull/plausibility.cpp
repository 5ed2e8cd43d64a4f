#include "parametric_hull/plausibility.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hullopt::hull {
namespace {

std::string PlausibilityNumber(double v) {
  std::ostringstream s;
  s.precision(4);
  s << v;
  return s.str();
}

// Largest half-breadth of a body below the waterline z = T (contours interpolated at T).
double MaxHalfBreadthBelow(const Demihull& body, double T) {
  double b = 0.0;
  for (const auto& st : body.stations) {
    for (std::size_t i = 0; i < st.y_m.size(); ++i) {
      if (st.z_m[i] <= T) b = std::max(b, st.y_m[i]);
      if (i > 0 && st.z_m[i - 1] < T && st.z_m[i] > T) {
        const double f = (T - st.z_m[i - 1]) / (st.z_m[i] - st.z_m[i - 1]);
        b = std::max(b, st.y_m[i - 1] + f * (st.y_m[i] - st.y_m[i - 1]));
      }
    }
  }
  return b;
}

// Span of the stations whose keel is below the waterline.
double WettedSpan(const Demihull& body, double T) {
  double x0 = 0, x1 = 0;
  bool any = false;
  for (const auto& st : body.stations) {
    if (st.z_m.empty() || !(st.z_m.front() < T)) continue;
    if (!any) x0 = st.x_m;
    x1 = st.x_m;
    any = true;
  }
  return any ? x1 - x0 : 0.0;
}

}  // namespace

double DemihullClearance(const HullForm& hull, const Hydrostatics& hs) {
  if (hull.bodies.empty()) return 0.0;
  const Demihull& main = hull.bodies.front();
  const double T = hull.draught_m;
  const double main_half = MaxHalfBreadthBelow(main, T);
  double clearance = 0.0;
  bool any = false;
  auto take = [&](double c) {
    clearance = any ? std::min(clearance, c) : c;
    any = true;
  };
  // A mirrored main body (y_centre > 0) is a pair of demihulls: gap between the two.
  if (main.y_centre_m > 0.0) take(2.0 * (main.y_centre_m - main_half));
  for (std::size_t i = 1; i < hull.bodies.size(); ++i) {
    const Demihull& b = hull.bodies[i];
    const double half = MaxHalfBreadthBelow(b, T);
    take(std::fabs(b.y_centre_m - main.y_centre_m) - main_half - half);
    if (b.y_centre_m > 0.0) take(2.0 * (b.y_centre_m - half));
  }
  (void)hs;
  return any ? clearance : 0.0;
}

std::vector<PlausibilityFinding> CheckHullPlausibility(const HullForm& hull, const Hydrostatics& hs,
                                                       const PlausibilityLimits& lim) {
  std::vector<PlausibilityFinding> out;
  auto refuse = [&](const std::string& q, const std::string& m) { out.push_back({q, m, true}); };
  const bool swath = hull.type == "swath";
  // A length override first, then the units: either error makes every other rule fire, and these name
  // the cause.
  if (!hull.bodies.empty() && hull.length_m > 0.0) {
    const double span = WettedSpan(hull.bodies.front(), hull.draught_m);
    if (span > 0 && (hull.length_m > lim.length_override_factor * span ||
                     hull.length_m < span / lim.length_override_factor))
      refuse("length_m", "length_m = " + PlausibilityNumber(hull.length_m) + " m is not within a factor " +
                             PlausibilityNumber(lim.length_override_factor) + " of the wetted stations' span " + PlausibilityNumber(span) +
                             " m (the form coefficients would be Cb " + PlausibilityNumber(hs.Cb) + ", Cp " + PlausibilityNumber(hs.Cp) + ")");
    if (!out.empty()) return out;
  }
  const double L_over_T = hs.L_m / hs.T_m, L_over_B = hs.B_m > 0 ? hs.L_m / hs.B_m : INFINITY;
  if (L_over_T > lim.max_L_over_T || L_over_B > lim.max_L_over_B) {
    // Ten times the limits is no design at all: the factor 1000 of mm against m is the likely cause.
    const bool mm = L_over_T > 10 * lim.max_L_over_T || L_over_B > 10 * lim.max_L_over_B;
    refuse("L", "L/T = " + PlausibilityNumber(L_over_T) + ", L/B = " + PlausibilityNumber(L_over_B) + " (L " + PlausibilityNumber(hs.L_m) + " m, B " +
                    PlausibilityNumber(hs.B_m) + " m, T " + PlausibilityNumber(hs.T_m) + " m) are not a ship's (limits L/T <= " +
                    PlausibilityNumber(lim.max_L_over_T) + ", L/B <= " + PlausibilityNumber(lim.max_L_over_B) + ")" +
                    (mm ? ": the offsets are probably in millimetres while draught_m is in metres (give x_m, "
                          "y_m, z_m in metres)"
                        : ": check that the offsets and draught_m use the same unit (metres)"));
    return out;
  }
  const std::pair<const char*, double> coeffs[] = {
      {"Cb", hs.Cb}, {"Cp", hs.Cp}, {"Cm", hs.Cm}, {"Cwp", hs.Cwp}};
  for (const auto& [name, v] : coeffs)
    if (!(std::isfinite(v) && v > 0.0 && v <= 1.0 + 1e-9))  // 1e-9: round-off of a box-shaped hull
      refuse(name, std::string(name) + " = " + PlausibilityNumber(v) + " must lie in (0, 1] (L " + PlausibilityNumber(hs.L_m) + " m, B " +
                       PlausibilityNumber(hs.B_m) + " m, T " + PlausibilityNumber(hs.T_m) + " m)");
  if (!out.empty()) return out;
  // Consistency: Cb = Cp Cm with Cm <= 1 implies Cb <= Cp; Cvp = Cb / Cwp <= 1 unless the hull is widest
  // below the waterline (a SWATH or a bulb).
  if (hs.Cb > hs.Cp * (1 + 1e-9))
    refuse("Cb", "Cb = " + PlausibilityNumber(hs.Cb) + " exceeds Cp = " + PlausibilityNumber(hs.Cp) + " (Cm = Cb/Cp > 1)");
  if (!swath && hull.type != "offsets" && hull.type != "stl" && hs.Cvp > 1.0 + 1e-9)
    refuse("Cvp", "Cvp = " + PlausibilityNumber(hs.Cvp) + " > 1 for a " + hull.type + " (only a SWATH is wider below the "
                  "waterline than at it)");
  if (!(std::fabs(hs.LCB_pct_L) < 50.0))
    refuse("LCB", "LCB = " + PlausibilityNumber(hs.LCB_pct_L) + " % L from midships lies outside the hull (|LCB| < 50 % L)");
  if (!(std::fabs(hs.LCF_pct_L) < 50.0))
    refuse("LCF", "LCF = " + PlausibilityNumber(hs.LCF_pct_L) + " % L from midships lies outside the hull (|LCF| < 50 % L)");
  if (hull.bodies.size() > 1 || (!hull.bodies.empty() && hull.bodies.front().y_centre_m > 0.0)) {
    const double c = DemihullClearance(hull, hs);
    if (!(c > 0.0))
      refuse("spacing", "the hulls overlap: clearance between them " + PlausibilityNumber(c) + " m (centre spacing " +
                            PlausibilityNumber(2.0 * hull.bodies.front().y_centre_m) + " m, demihull beam " + PlausibilityNumber(hs.B_m) +
                            " m); the spacing must exceed the beam");
  }
  return out;
}

std::vector<PlausibilityFinding> CheckMassPlausibility(const MassProperties& m, const Hydrostatics& hs,
                                                       bool accept_mass_mismatch, const PlausibilityLimits& lim) {
  std::vector<PlausibilityFinding> out;
  const double ratio = m.mass_kg / hs.displacement_kg;
  if (!(std::fabs(ratio - 1.0) <= lim.mass_tolerance)) {
    const std::string msg = "mass_kg = " + PlausibilityNumber(m.mass_kg) + " is " + PlausibilityNumber(100.0 * (ratio - 1.0)) +
                            " % from the displaced mass " + PlausibilityNumber(hs.displacement_kg) + " kg at the draught " +
                            PlausibilityNumber(hs.T_m) + " m (tolerance " + PlausibilityNumber(100.0 * lim.mass_tolerance) +
                            " %): the hull would float at another draught";
    out.push_back({"mass_kg", accept_mass_mismatch ? msg + " (accepted by mass.accept_mass_mismatch)"
                                                   : msg + "; set mass.accept_mass_mismatch: true to go on",
                   !accept_mass_mismatch});
  }
  const double L = hs.L_m;
  if (!(m.kyy_m >= lim.kyy_min_over_L * L && m.kyy_m <= lim.kyy_max_over_L * L))
    out.push_back({"kyy_m", "kyy_m = " + PlausibilityNumber(m.kyy_m) + " m is " + PlausibilityNumber(m.kyy_m / L) + " L; it must lie in [" +
                                PlausibilityNumber(lim.kyy_min_over_L) + ", " + PlausibilityNumber(lim.kyy_max_over_L) + "] L (L " + PlausibilityNumber(L) +
                                " m; all mass at the ends gives 0.5 L)",
                   true});
  else if (m.kyy_m < lim.kyy_usual_min_over_L * L || m.kyy_m > lim.kyy_usual_max_over_L * L)
    out.push_back({"kyy_m", "kyy_m = " + PlausibilityNumber(m.kyy_m / L) + " L is outside the usual " +
                                PlausibilityNumber(lim.kyy_usual_min_over_L) + "-" + PlausibilityNumber(lim.kyy_usual_max_over_L) + " L",
                   false});
  if (!(m.kg_m > 0.0 && m.kg_m <= lim.kg_max_over_L * L))
    out.push_back({"kg_m", "kg_m = " + PlausibilityNumber(m.kg_m) + " m must lie in (0, " + PlausibilityNumber(lim.kg_max_over_L) +
                               " L] = (0, " + PlausibilityNumber(lim.kg_max_over_L * L) + "] m above the baseline",
                   true});
  return out;
}

}  // namespace hullopt::hull
