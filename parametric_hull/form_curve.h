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
#include <vector>

namespace hullopt::hull {

struct FormCurve {
  double xi_peak = 0.5;    ///< ξ_m, position of the peak
  double peak = 1.0;       ///< f(ξ_m)
  double aft_ratio = 0.0;  ///< r = f(0)/peak
  double exponent = 2.0;   ///< q, entrance exponent (> 0)
  double run_ratio = 1.0;  ///< k = p/q, run exponent over entrance exponent
  /// A blend of family members (empty: this curve is the single member above): f = Σ w_i f_i with weights
  /// summing to 1. Area and moment are linear in f, so a blend of curves that all meet the same area, centroid
  /// and end values meets them too. `peak` is then Σ w_i peak_i, an upper bound of the blend's maximum.
  std::vector<FormCurve> members;
  std::vector<double> weights;

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
/// <= good_enough is taken, else the lowest-scoring ones (default score: the peak) are blended: every member
/// with a score s_i < s_min + kCurveScoreBand gets the weight max(0, 1 - (s_i - s_min)/kCurveScoreBand),
/// normalised. The weights are continuous in the scores, so the curve does not jump where two run ratios
/// swap places as the best (a lone best member, more than the band ahead, is returned as it is). The blend's
/// score is at most s_min + kCurveScoreBand for a score that is a maximum over ξ of a quantity linear in f
/// (the generator's fullest-section score). A warm start that is a blend keeps its weights and re-solves its
/// members.
FormCurve SolveFormCurveAtMidship(double end_value, double area, double centroid, const std::string& what,
                                  const FormCurve* warm_start = nullptr, const CurveScore& score = nullptr,
                                  double good_enough = 0.0);

/// Width of the score band over which SolveFormCurveAtMidship blends near-best members (in the score's units:
/// a section area coefficient for the generator, the peak / midship area for the default score).
constexpr double kCurveScoreBand = 0.002;

}  // namespace hullopt::hull
