#pragma once
// Longitudinal form curves (sectional area curve, waterplane half-breadth curve) on the normalised length
// ξ ∈ [0, 1] from AP to FP. One family for both: a peak of height `peak` at ξ_m, falling to the bow as
// 1 - u^q (u = (ξ-ξ_m)/(1-ξ_m)) and to the stern as 1 - (1 - r) v^p (v = (ξ_m-ξ)/ξ_m), r = f(0)/peak the
// transom ratio. The exponents set the fullness of entrance (q) and run (p), ξ_m the centroid. Area and first
// moment are closed forms. For a given ratio k = p/q the two unknowns (ξ_m, q) are found by a grid search and
// a 2x2 Newton iteration on the exact integrals; k = 1 is tried first, then ratios further from 1, so the
// curve is as even as the targets allow (docs/hull-generator.md, 'Generator
// (parametric_hull/hull_generator.h)', step 1: form parameters with a power-law basis).
#include <functional>
#include <string>

namespace hullopt::hull {

struct FormCurve {
  double xi_peak = 0.5;    ///< ξ_m, position of the peak
  double peak = 1.0;       ///< f(ξ_m)
  double aft_ratio = 0.0;  ///< r = f(0)/peak
  double exponent = 2.0;   ///< q, entrance exponent (> 0)
  double run_ratio = 1.0;  ///< k = p/q, run exponent over entrance exponent

  double operator()(double xi) const;
  double Area() const;    ///< ∫_0^1 f dξ
  double Moment() const;  ///< ∫_0^1 ξ f dξ
};

/// Curve with a given peak height, f(0) = end_value, ∫f = area and centroid ∫ξf/∫f = centroid (waterplane:
/// peak 1, area Cwp, centroid 0.5 + LCF/100). Throws std::domain_error naming `what` and the numbers if no
/// member of the family meets them.
/// warm_start: a previous solution for nearby targets, tried first (same k) to save the search.
FormCurve SolveFormCurveWithPeak(double peak, double end_value, double area, double centroid,
                                 const std::string& what, const FormCurve* warm_start = nullptr);

/// A figure of merit of a candidate curve (lower is better).
using CurveScore = std::function<double(const FormCurve&)>;

/// Curve normalised at midships, f(0.5) = 1 (sectional area curve over the midship area: area Cp, centroid
/// 0.5 + LCB/100, f(0) the transom area ratio). The peak may exceed 1 when the area lies far aft. Among the
/// family members that meet the targets (run/entrance ratios tried evenest first) the first with a score
/// <= good_enough is taken, else the one with the lowest score (default score: the peak).
FormCurve SolveFormCurveAtMidship(double end_value, double area, double centroid, const std::string& what,
                                  const FormCurve* warm_start = nullptr, const CurveScore& score = nullptr,
                                  double good_enough = 0.0);

}  // namespace hullopt::hull
