#include "parametric_hull/form_curve.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace hullopt::hull {

double FormCurve::operator()(double xi) const {
  if (!members.empty()) {
    double f = 0.0;
    for (size_t i = 0; i < members.size(); ++i) f += weights[i] * members[i](xi);
    return f;
  }
  if (xi >= xi_peak) {
    const double u = xi_peak < 1.0 ? std::min(1.0, (xi - xi_peak) / (1.0 - xi_peak)) : 0.0;
    return peak * (1.0 - std::pow(u, exponent));
  }
  const double v = std::min(1.0, std::max(0.0, (xi_peak - xi) / xi_peak));
  return peak * (1.0 - (1.0 - aft_ratio) * std::pow(v, exponent * run_ratio));
}

double FormCurve::Area() const {
  if (!members.empty()) {
    double a = 0.0;
    for (size_t i = 0; i < members.size(); ++i) a += weights[i] * members[i].Area();
    return a;
  }
  const double q = exponent, p = exponent * run_ratio, m = xi_peak, r = aft_ratio;
  return peak * ((1.0 - m) * q / (q + 1.0) + m * (1.0 - (1.0 - r) / (p + 1.0)));
}

double FormCurve::Moment() const {
  if (!members.empty()) {
    double m = 0.0;
    for (size_t i = 0; i < members.size(); ++i) m += weights[i] * members[i].Moment();
    return m;
  }
  const double q = exponent, p = exponent * run_ratio, m = xi_peak, r = aft_ratio;
  // ∫_0^1 u (1-u^q) du = 1/2 - 1/(q+2); ∫_0^1 (1-v)(1-(1-r)v^p) dv = 1/2 - (1-r)(1/(p+1) - 1/(p+2)).
  const double fore = (1.0 - m) * (m * q / (q + 1.0) + (1.0 - m) * (0.5 - 1.0 / (q + 2.0)));
  const double aft = m * m * (0.5 - (1.0 - r) * (1.0 / (p + 1.0) - 1.0 / (p + 2.0)));
  return peak * (fore + aft);
}

namespace {

// Exponent range of the family: 0.25 is a very hollow curve (fullness 0.2), 60 nearly a box.
constexpr double kMinLogP = -1.386, kMaxLogP = 4.09;
constexpr double kMinXi = 0.01, kMaxXi = 0.99;
// Run/entrance exponent ratios tried, evenest first.
constexpr double kRunRatios[] = {1.0,     1.5,  1 / 1.5,  2.25, 1 / 2.25, 3.4,  1 / 3.4, 5.0, 1 / 5.0, 8.0,
                                 1 / 8.0, 12.0, 1 / 12.0, 20.0, 1 / 20.0, 35.0, 1 / 35.0};
// The solved curve must meet area (relative) and centroid (in units of L) to this: far below the generator's
// targets; the hydrostatic re-targeting then removes the discretisation error.
constexpr double kSolveTol = 1e-11;

// Maker: bool(double xi, double log q, double k, FormCurve*); Residual: bool(const FormCurve&, Vector2d*).
// Templates rather than std::function: the grid search below evaluates them tens of thousands of times.
template <class Maker, class Residual>
bool Eval(const Maker& make, const Residual& res, double xi, double lq, double k, Eigen::Vector2d* r) {
  FormCurve c;
  return make(xi, lq, k, &c) && res(c, r);
}

template <class Maker, class Residual>
bool Newton(const Maker& make, const Residual& res, double k, double* xi, double* lq) {
  Eigen::Vector2d r, r1;
  for (int it = 0; it < 50; ++it) {
    if (!Eval(make, res, *xi, *lq, k, &r)) return false;
    if (r.norm() < kSolveTol) return true;
    Eigen::Matrix2d J;
    const double h = 1e-7;
    if (Eval(make, res, *xi + h, *lq, k, &r1)) {
      J.col(0) = (r1 - r) / h;
    } else if (Eval(make, res, *xi - h, *lq, k, &r1)) {
      J.col(0) = (r - r1) / h;
    } else {
      return false;
    }
    if (!Eval(make, res, *xi, *lq + h, k, &r1)) return false;
    J.col(1) = (r1 - r) / h;
    const Eigen::Vector2d step = J.fullPivLu().solve(-r);
    if (!step.allFinite()) return false;
    double lambda = 1.0;
    bool moved = false;
    for (int s = 0; s < 30 && !moved; ++s, lambda *= 0.5) {
      const double nx = *xi + lambda * step(0), nl = *lq + lambda * step(1);
      Eigen::Vector2d rn;
      if (nx > 0.5 * kMinXi && nx < 1.0 - 0.5 * kMinXi && nl > kMinLogP - 0.5 && nl < kMaxLogP + 1.0 &&
          Eval(make, res, nx, nl, k, &rn) && rn.norm() < r.norm()) {
        *xi = nx;
        *lq = nl;
        moved = true;
      }
    }
    if (!moved) return false;
  }
  return Eval(make, res, *xi, *lq, k, &r) && r.norm() < kSolveTol;
}

// The member of run ratio k nearest the start (xi, lq), by Newton; false if it does not converge.
template <class Maker, class Residual>
bool SolveMember(const Maker& make, const Residual& res, double k, double xi, double lq, FormCurve* out) {
  return Newton(make, res, k, &xi, &lq) && make(xi, lq, k, out);
}

// The weighted blend of `members` (one member: that member itself).
FormCurve Blend(std::vector<FormCurve> members, std::vector<double> weights) {
  if (members.size() == 1) return members[0];
  FormCurve b;
  b.peak = 0.0;
  for (size_t i = 0; i < members.size(); ++i) b.peak += weights[i] * members[i].peak;
  b.xi_peak = members[0].xi_peak;
  b.aft_ratio = members[0].aft_ratio;
  b.exponent = members[0].exponent;
  b.run_ratio = members[0].run_ratio;
  b.members = std::move(members);
  b.weights = std::move(weights);
  return b;
}

// Solves for the curve. Without a usable warm start, tries the run/entrance ratios in turn: the first that
// solves (evenest exponents) if there is no score, else the first with a score <= good_enough or else the
// blend of the lowest-scoring ones (form_curve.h, SolveFormCurveAtMidship). A warm start is re-solved member
// by member at its own run ratios and keeps its weights.
template <class Maker, class Residual>
bool Solve(const Maker& make, const Residual& res, const FormCurve* warm, const CurveScore* score,
           double good_enough, FormCurve* out) {
  const bool lowest_peak = score != nullptr;
  if (warm) {
    const std::vector<FormCurve> start = warm->members.empty() ? std::vector<FormCurve>{*warm} : warm->members;
    std::vector<FormCurve> solved(start.size());
    bool all = true;
    for (size_t i = 0; i < start.size() && all; ++i)
      all = SolveMember(make, res, start[i].run_ratio, start[i].xi_peak, std::log(start[i].exponent), &solved[i]);
    if (all) {
      *out = Blend(std::move(solved), warm->members.empty() ? std::vector<double>{1.0} : warm->weights);
      return true;
    }
  }
  std::vector<FormCurve> candidates;
  std::vector<double> scores;
  for (double k : kRunRatios) {
    double best = INFINITY, bx = 0.5, bl = 0.0;
    Eigen::Vector2d r;
    for (int i = 0; i <= 48; ++i) {
      const double x = kMinXi + (kMaxXi - kMinXi) * i / 48.0;
      for (int j = 0; j <= 30; ++j) {
        const double lq = kMinLogP + (kMaxLogP - kMinLogP) * j / 30.0;
        if (Eval(make, res, x, lq, k, &r) && r.norm() < best) {
          best = r.norm();
          bx = x;
          bl = lq;
        }
      }
    }
    FormCurve c;
    if (std::isfinite(best) && Newton(make, res, k, &bx, &bl) && make(bx, bl, k, &c)) {
      if (!lowest_peak) {
        *out = c;
        return true;
      }
      const double sc = (*score)(c);
      if (sc <= good_enough) {  // evenest curve that is comfortably feasible
        *out = c;
        return true;
      }
      candidates.push_back(c);
      scores.push_back(sc);
    }
  }
  if (candidates.empty()) return false;
  const double s_min = *std::min_element(scores.begin(), scores.end());
  std::vector<FormCurve> members;
  std::vector<double> weights;
  double total = 0.0;
  for (size_t i = 0; i < candidates.size(); ++i) {
    const double w = 1.0 - (scores[i] - s_min) / kCurveScoreBand;
    if (w <= 0.0) continue;
    members.push_back(candidates[i]);
    weights.push_back(w);
    total += w;
  }
  for (double& w : weights) w /= total;
  *out = Blend(std::move(members), std::move(weights));
  return true;
}

[[noreturn]] void Refuse(const std::string& what, double area, double centroid, const std::string& hint) {
  std::ostringstream s;
  s << what << ": no fair curve has area " << area << " and centroid at " << (centroid - 0.5) * 100.0
    << " % L from midships (rule: a curve this full cannot have its centroid that far from midships; a full "
       "curve needs its centroid near midships)"
    << hint;
  throw std::domain_error(s.str());
}

auto CurveTargets(double area, double centroid) {
  return [=](const FormCurve& c, Eigen::Vector2d* r) {
    const double a = c.Area();
    (*r)(0) = (a - area) / area;
    (*r)(1) = c.Moment() / a - centroid;
    return true;
  };
}

}  // namespace

FormCurve SolveFormCurveWithPeak(double peak, double end_value, double area, double centroid,
                                 const std::string& what, const FormCurve* warm_start) {
  if (!(end_value <= peak))
    throw std::domain_error(what + ": end value " + std::to_string(end_value) + " exceeds the peak " +
                            std::to_string(peak));
  if (!(area < peak))
    throw std::domain_error(what + ": area " + std::to_string(area) + " must be below the peak " +
                            std::to_string(peak));
  const auto make = [=](double xi, double lq, double k, FormCurve* c) {
    c->xi_peak = xi;
    c->exponent = std::exp(lq);
    c->run_ratio = k;
    c->peak = peak;
    c->aft_ratio = end_value / peak;
    return true;
  };
  FormCurve c;
  if (!Solve(make, CurveTargets(area, centroid), warm_start, nullptr, 0.0, &c))
    Refuse(what, area, centroid, centroid < 0.5 ? "; a wider transom (transom_beam_ratio) moves it aft" : "");
  return c;
}

FormCurve SolveFormCurveAtMidship(double end_value, double area, double centroid, const std::string& what,
                                  const FormCurve* warm_start, const CurveScore& score, double good_enough) {
  // For given (ξ_m, exponents) the peak M follows from f(0.5) = 1: forward of the peak f(0.5) = M(1-u^q);
  // aft of it M - (M - f0) v^p = 1.
  const auto make = [=](double xi, double lq, double k, FormCurve* t) {
    t->xi_peak = xi;
    t->exponent = std::exp(lq);
    t->run_ratio = k;
    double M;
    if (xi <= 0.5) {
      M = 1.0 / (1.0 - std::pow((0.5 - xi) / (1.0 - xi), t->exponent));
    } else {
      const double vp = std::pow((xi - 0.5) / xi, t->exponent * k);
      M = (1.0 - end_value * vp) / (1.0 - vp);
    }
    if (!std::isfinite(M) || M < end_value || M > 2.0) return false;  // peak over 2x midships: not a ship
    t->peak = M;
    t->aft_ratio = end_value / M;
    return true;
  };
  FormCurve c;
  const CurveScore by_peak = [](const FormCurve& f) { return f.peak; };
  if (!Solve(make, CurveTargets(area, centroid), warm_start, score ? &score : &by_peak, good_enough, &c))
    Refuse(what, area, centroid, centroid < 0.5 ? "; a deeper transom (transom_immersion) moves it aft" : "");
  return c;
}

}  // namespace hullopt::hull
