#pragma once
// Slender hulls of semicircular sections centred on the water line, whose radius may taper linearly to 0.1 R0
// over the aft or the fore half: the hulls of the g -> 0 closed forms (docs/theory.md, "Closed forms in the
// φ = 0 limit").
#include <cmath>

#include "parametric_hull/hull_form.h"

namespace hullopt::test {

enum class Taper { kNone, kAft, kFore };

struct SemicircleHullShape {
  double length_m = 3.0;
  double radius_m = 0.12;   ///< R0
  double draught_m = 0.2;   ///< water line above the baseline
};

/// Radius at x from the AP: 0.1 R0 at the tapered end, linear over that half, R0 elsewhere.
inline double SemicircleRadius(const SemicircleHullShape& s, Taper taper, double x) {
  const double h = 0.5 * s.length_m;
  if (taper == Taper::kAft && x < h) return s.radius_m * (0.1 + 0.9 * x / h);
  if (taper == Taper::kFore && x > h) return s.radius_m * (0.1 + 0.9 * (s.length_m - x) / h);
  return s.radius_m;
}

/// 61 stations of 24 arc segments with the radius radius(x) [m] at x [m from the AP], each wall-sided 0.05 m
/// above the water line.
template <class Radius>
hull::HullForm SemicircleHullOf(const SemicircleHullShape& s, Radius radius) {
  hull::Demihull b;
  b.role = "main";
  constexpr int kStations = 61, kArc = 24;
  for (int i = 0; i < kStations; ++i) {
    const double x = s.length_m * i / (kStations - 1), R = radius(x);
    hull::Station st{x, {}, {}};
    for (int k = 0; k <= kArc; ++k) {
      const double a = -0.5 * M_PI * (1.0 - static_cast<double>(k) / kArc);  // keel −π/2 .. waterline 0
      st.y_m.push_back(k == 0 ? 0.0 : R * std::cos(a));
      st.z_m.push_back(s.draught_m + R * std::sin(a));
    }
    st.y_m.push_back(R), st.z_m.push_back(s.draught_m + 0.05);
    b.stations.push_back(st);
  }
  hull::HullForm h;
  h.type = "monohull";
  h.draught_m = s.draught_m;
  h.length_m = s.length_m;
  h.bodies = {b};
  return h;
}

/// The tapered hulls (the taper is linear, so the strip geometry's interpolation is exact).
inline hull::HullForm SemicircleHull(const SemicircleHullShape& s, Taper taper) {
  return SemicircleHullOf(s, [&](double x) { return SemicircleRadius(s, taper, x); });
}

}  // namespace hullopt::test
