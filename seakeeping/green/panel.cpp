#include "seakeeping/green/panel.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace hullopt::sk {
namespace {

using Point = std::array<double, 2>;

// Signed turning [rad] of the polyline at its interior vertex k (positive: left turn, i.e. convex for a half
// contour run from the keel to the waterline with the body on its left).
double Kink(const std::vector<Point>& c, std::size_t k) {
  const double ax = c[k][0] - c[k - 1][0], az = c[k][1] - c[k - 1][1];
  const double bx = c[k + 1][0] - c[k][0], bz = c[k + 1][1] - c[k][1];
  return std::atan2(ax * bz - az * bx, ax * bx + az * bz);
}


// Arc length along the polyline c (cumulative, s[0] = 0).
std::vector<double> ArcLength(const std::vector<Point>& c) {
  std::vector<double> s(c.size(), 0.0);
  for (std::size_t i = 1; i < c.size(); ++i) s[i] = s[i - 1] + std::hypot(c[i][0] - c[i - 1][0], c[i][1] - c[i - 1][1]);
  return s;
}

// std::upper_bound on a sorted vector, walked from the previous answer: O(1) a call when the values asked
// move in small steps (a sweep), the same index as the binary search (which is taken for NaN).
class SortedCursor {
 public:
  explicit SortedCursor(const std::vector<double>& v) : v_(v) {}
  int FirstAbove(double x) {
    if (std::isnan(x)) return static_cast<int>(std::upper_bound(v_.begin(), v_.end(), x) - v_.begin());
    while (i_ > 0 && v_[i_ - 1] > x) --i_;
    while (i_ < static_cast<int>(v_.size()) && v_[i_] <= x) ++i_;
    return i_;
  }

 private:
  const std::vector<double>& v_;
  int i_ = 0;
};

// The point at arc length si along the polyline c (cumulative arc length s); `cursor` walks s.
Point PointAt(const std::vector<Point>& c, const std::vector<double>& s, double si, SortedCursor& cursor) {
  const std::size_t nv = c.size();
  const std::size_t k = std::clamp<std::size_t>(static_cast<std::size_t>(cursor.FirstAbove(si)), 1, nv - 1);
  const double seg = s[k] - s[k - 1];
  const double f = seg > 0 ? std::clamp((si - s[k - 1]) / seg, 0.0, 1.0) : 0.0;
  return Point{c[k - 1][0] + f * (c[k][0] - c[k - 1][0]), c[k - 1][1] + f * (c[k][1] - c[k - 1][1])};
}

// std::lround(x) without the libm call for 0 <= x < 2^30 (x − floor(x) is exact there), std::lround
// otherwise.
int RoundHalfUp(double x) {
  if (!(x >= 0.0 && x < 1073741824.0)) return static_cast<int>(std::lround(x));
  const double f = std::floor(x);
  return static_cast<int>(f) + (x - f >= 0.5 ? 1 : 0);
}

// Where hypot(dx, dz) lies against a distance r > 0, read from the squares dx² + dz² and r² where they settle
// it: the squares carry a few rounding units, so a relative gap of 1e-9 decides; nearer the tie, or where the
// squares could underflow or overflow, kUnsure (the caller then takes hypot itself). Comparing lengths this
// way costs a multiply-add instead of a libm hypot and gives the same decisions as comparing hypot.
enum class Side { kBelow, kAbove, kUnsure };

Side SideOf(double d2, double r) {
  constexpr double kMargin = 1e-9, kTiny = 1e-290, kHuge = 1e290;
  const double r2 = r * r;
  if (!(d2 > kTiny && d2 < kHuge && r2 > kTiny && r2 < kHuge)) return Side::kUnsure;  // NaN too
  if (d2 < r2 * (1.0 - kMargin)) return Side::kBelow;
  if (d2 > r2 * (1.0 + kMargin)) return Side::kAbove;
  return Side::kUnsure;
}

double Squared(const Point& a, const Point& b) {
  const double dy = a[0] - b[0], dz = a[1] - b[1];
  return dy * dy + dz * dz;
}

// A piece of contour whose direction turns by Θ in all (the sum of its |kinks|) has a chord of at least its
// length × cos(Θ/2). So two of its points are across a fold (chord < length / fold_ratio) only where the
// contour turns between them by more than this (1e-6 rad below the bound, far above the rounding of sums of
// kinks); -1 where every pair has to be looked at (fold_ratio <= 1).
double FoldTurn(double fold_ratio) {
  return fold_ratio > 1.0 && std::isfinite(fold_ratio) ? 2.0 * std::acos(1.0 / fold_ratio) - 1e-6 : -1.0;
}

// Cumulative |turning| of the polyline c (arc length s, vertex kinks `kink`) at the arc positions `at`
// (increasing): every vertex up to the position counts, an upper bound on the turning from the keel there.
// Empty where the kinks may miss turning (a segment so short, or a contour so large, that the products in
// Kink underflow or overflow; a repeated point has no direction): then no pair may be skipped.
std::vector<double> TurningAt(const std::vector<double>& s, const std::vector<double>& kink,
                              const std::vector<double>& at) {
  if (!(s.back() < 1e100)) return {};
  for (std::size_t k = 1; k < s.size(); ++k)
    if (!(s[k] - s[k - 1] > 1e-100)) return {};
  std::vector<double> turned(at.size(), 0.0);
  double sum = 0.0;
  std::size_t k = 1;
  for (std::size_t m = 0; m < at.size(); ++m) {
    while (k + 1 < s.size() && s[k] <= at[m]) sum += std::fabs(kink[k++]);
    turned[m] = sum;
  }
  return turned;
}

// Folds thinner than `limit` (a fin whose two faces lie closer than `limit` though far apart along the
// contour) replaced by the straight segment across their root: constant-strength source panels cannot
// represent a part much thinner than they are long (the system of facing panels is near-singular, its
// condition growing like length/thickness), and with the panel count given they cannot be made that short.
std::vector<Point> CutThinFolds(const std::vector<Point>& c, double limit, double fold_ratio) {
  const std::vector<double> s = ArcLength(c);
  const double S = s.back();
  const int M = 200;
  std::vector<Point> p(M + 1);
  std::vector<double> sp(M + 1);
  SortedCursor along_s(s);
  for (int m = 0; m <= M; ++m) sp[m] = S * m / M, p[m] = PointAt(c, s, sp[m], along_s);
  std::vector<std::array<double, 2>> cuts;  // [s_a, s_b] removed
  // Whether q lies across a thin part from m: closer than `limit` in space and fold_ratio times farther along
  // the contour. The squares settle it for all but near-ties (SideOf); hypot only for those. Most candidates
  // are farther than `limit`: one comparison of squares drops them (margin 1e-9 over their rounding, where
  // the squares can neither underflow nor overflow).
  const bool squares_ok = limit >= 1e-100 && limit <= 1e100 && S <= 1e100;
  const double limit2 = limit * limit * (1.0 + 1e-9);
  auto across = [&](int m, int q) {
    const double d2 = Squared(p[q], p[m]);
    if (squares_ok && d2 > limit2) return false;
    const double along = S * (q - m) / M;
    const Side near = SideOf(d2, limit);
    if (near == Side::kAbove) return false;
    const Side folded = fold_ratio > 0.0 && along > 0.0 ? SideOf(d2, along / fold_ratio) : Side::kUnsure;
    if (folded == Side::kAbove) return false;
    if (near == Side::kBelow && folded == Side::kBelow) return true;
    const double d = std::hypot(p[q][0] - p[m][0], p[q][1] - p[m][1]);
    return d < limit && along > fold_ratio * std::max(d, 1e-300);
  };
  // Only points past enough turning can be across (FoldTurn): for a hull section, none or a few per point.
  std::vector<double> kink(c.size(), 0.0);
  for (std::size_t k = 1; k + 1 < c.size(); ++k) kink[k] = Kink(c, k);
  const std::vector<double> turned = TurningAt(s, kink, sp);
  const double fold_turn = FoldTurn(fold_ratio);
  const bool prune = fold_turn > 0.0 && !turned.empty() && std::isfinite(turned.back());
  SortedCursor by_turning(turned);
  for (int m = 0; m <= M; ++m) {
    if (!cuts.empty() && S * m / M <= cuts.back()[1]) continue;
    int partner = -1;
    const int q_end = prune ? std::max(by_turning.FirstAbove(turned[m] + fold_turn) - 1, m) : m;
    for (int q = M; q > q_end; --q) {  // the farthest point across: the whole fin goes
      if (across(m, q)) {
        partner = q;
        break;
      }
    }
    if (partner > m + 1) cuts.push_back({S * m / M, S * partner / M});
  }
  if (cuts.empty()) return c;
  std::vector<Point> out;
  std::size_t g = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    while (g < cuts.size() && s[i] > cuts[g][1]) ++g;
    if (g < cuts.size() && s[i] >= cuts[g][0]) {
      if (out.empty() || s[i - 1] < cuts[g][0]) {  // entering the cut: its root on both faces
        SortedCursor from_start(s);
        out.push_back(PointAt(c, s, cuts[g][0], from_start));
        out.push_back(PointAt(c, s, cuts[g][1], from_start));
      }
      continue;
    }
    out.push_back(c[i]);
  }
  return out;
}

}  // namespace

std::vector<Panel> PanelSymmetricSection(const std::vector<std::array<double, 2>>& raw, int n_panels,
                                         double y_centre_m, const PanelSpacing& spacing) {
  if (raw.size() < 2) throw std::invalid_argument("section contour needs at least 2 points");
  if (n_panels < 4 || n_panels % 2 != 0)
    throw std::invalid_argument("panels per section must be even and >= 4, got " + std::to_string(n_panels));
  const double scale = std::fabs(raw.front()[1]) + 1e-300;
  if (std::fabs(raw.front()[0]) > 1e-9 * scale + 1e-12)
    throw std::invalid_argument("section contour must start on the centreline (y = 0) at the keel");
  if (std::fabs(raw.back()[1]) > 1e-9 * scale + 1e-12)
    throw std::invalid_argument("section contour must end at the waterline (z = 0)");
  // Drop repeated points (zero-length segments have no direction).
  std::vector<Point> c{raw.front()};
  for (std::size_t i = 1; i < raw.size(); ++i)
    if (const Side side = SideOf(Squared(raw[i], c.back()), 1e-12 * scale);
        side == Side::kAbove ||
        (side == Side::kUnsure &&
         std::hypot(raw[i][0] - c.back()[0], raw[i][1] - c.back()[1]) > 1e-12 * scale))
      c.push_back(raw[i]);
  if (c.size() < 2) throw std::invalid_argument("section contour has zero girth");
  c.front()[0] = 0.0;
  c.back()[1] = 0.0;
  if (spacing.cut_thickness_fraction > 0.0) {
    const double girth = ArcLength(c).back();
    c = CutThinFolds(c, spacing.cut_thickness_fraction * girth / (n_panels / 2), spacing.fold_ratio);
  }
  // Cumulative arc length of the half contour, keel (s = 0) to waterline (s = S), and the vertex kinks.
  const std::size_t nv = c.size();
  std::vector<double> s(nv, 0.0), kink(nv, 0.0);
  for (std::size_t i = 1; i < nv; ++i) s[i] = s[i - 1] + std::hypot(c[i][0] - c[i - 1][0], c[i][1] - c[i - 1][1]);
  const double S = s.back();
  if (!(S > 0)) throw std::invalid_argument("section contour has zero girth");
  for (std::size_t k = 1; k + 1 < nv; ++k) kink[k] = Kink(c, k);
  SortedCursor along_s(s);
  auto at = [&](double si) { return PointAt(c, s, si, along_s); };
  const int nh = n_panels / 2;
  const double H = S / nh;  // uniform spacing

  // Corners: vertices turning by more than the corner angle become panel end points (the sharpest nh − 1).
  std::vector<std::size_t> corners;
  for (std::size_t k = 1; k + 1 < nv; ++k)
    if (std::fabs(kink[k]) > spacing.corner_angle_rad) corners.push_back(k);
  std::sort(corners.begin(), corners.end(),
            [&](std::size_t a, std::size_t b) { return std::fabs(kink[a]) > std::fabs(kink[b]); });
  if (corners.size() > static_cast<std::size_t>(nh - 1)) corners.resize(nh - 1);
  std::sort(corners.begin(), corners.end());
  std::vector<char> is_corner(nv, 0);
  for (std::size_t k : corners) is_corner[k] = 1;

  // Target spacing on a fine grid of the girth: the smallest of the uniform spacing, the spacing that turns
  // by at most max_turn_rad per panel (smooth curvature), a fraction of the local thickness, and a grading
  // towards the corners and the waterline end (where the source density and the memory kernel vary fastest).
  const int M = std::max(400, 40 * nh);
  std::vector<double> sg(M + 1), density(M + 1);
  for (int m = 0; m <= M; ++m) sg[m] = S * m / M;
  // Smooth turning |Θ|(s) at the grid points, cumulative: each non-corner vertex's |kink| spread linearly
  // over the halves of its two segments. In linear time: at grid point m the vertices (in order) whose ramp
  // is complete add |kink| each, a running sum kept vertex by vertex (`full`); those whose ramp has begun but
  // not ended are added term by term after it; the rest add nothing. That is the same sum in the same order
  // as adding every vertex's term at every m.
  std::vector<double> turn_at(M + 1, 0.0);
  {
    struct Ramp {
      double a, b, abs_kink;
      int m0;
    };
    std::vector<Ramp> ramps;
    for (std::size_t k = 1; k + 1 < nv; ++k) {
      if (is_corner[k] || kink[k] == 0.0) continue;
      const double a = 0.5 * (s[k - 1] + s[k]), b = 0.5 * (s[k] + s[k + 1]);
      ramps.push_back({a, b, std::fabs(kink[k]), std::clamp(static_cast<int>(std::floor(a / S * M)), 0, M)});
    }
    auto term = [&](const Ramp& r, int m) {
      return r.abs_kink * std::clamp((sg[m] - r.a) / (r.b - r.a), 0.0, 1.0);
    };
    std::size_t done = 0, begun = 0;  // ramps [0, done) complete at m, [done, begun) begun
    double full = 0.0;                // the running sum over the complete ones
    for (int m = 0; m <= M; ++m) {
      while (begun < ramps.size() && ramps[begun].m0 <= m) ++begun;
      while (done < begun && term(ramps[done], m) == ramps[done].abs_kink) full += ramps[done++].abs_kink;
      double t = full;
      for (std::size_t j = done; j < begun; ++j) t += term(ramps[j], m);
      turn_at[m] = t;
    }
  }
  // Local thickness on a coarser grid: the nearest contour point (of the half contour or its mirror image)
  // that is much farther along the contour than in space lies across a thin part.
  const int Mt = std::max(100, 10 * nh);
  std::vector<Point> pt(Mt + 1);
  std::vector<double> st(Mt + 1), thick(Mt + 1, std::numeric_limits<double>::infinity());
  for (int m = 0; m <= Mt; ++m) st[m] = S * m / Mt, pt[m] = at(st[m]);
  // Which pairs to look at. A thickness t acts only where thickness_fraction × t < H (below that h <= H
  // already), i.e. t < reach = H / thickness_fraction. And a piece of contour whose direction turns by Θ in
  // all has a chord of at least its length × cos(Θ/2), so q is across a fold from m (chord < length /
  // fold_ratio) only where the contour turns by more than 2 acos(1 / fold_ratio) between them: with the
  // cumulative |turning| K at the points (an upper bound: every vertex up to the point counts), those q are
  // an index range at either end (same side) or at the waterline end (through the keel, whose own kink adds).
  // Of the q looked at, the squares drop those certainly farther than reach, than the nearest so far or than
  // along / fold_ratio (a relative margin of 1e-9 over their rounding, where they can neither underflow nor
  // overflow, checked once); hypot and the original test for the rest. Each thickness that can act is thus
  // the nearest distance over all points, bit for bit; the others stay infinite or too large to act. For a
  // hull section (turning well under 2 acos(1/3) = 141° on one side) that is a few pairs per point.
  const double reach = spacing.thickness_fraction > 0.0 ? H / spacing.thickness_fraction * (1.0 + 1e-6)
                                                        : std::numeric_limits<double>::infinity();
  const double kMargin = 1.0 + 1e-9;
  const bool squares_ok = S / Mt > 1e-100 && S < 1e100 && spacing.fold_ratio >= 1e-50 &&
                          spacing.fold_ratio <= 1e50 && (reach >= 1e-100 || !std::isfinite(reach));
  const double reach2 = std::isfinite(reach) ? reach * reach : std::numeric_limits<double>::infinity();
  const double inv_fold2 = 1.0 / (spacing.fold_ratio * spacing.fold_ratio);
  const double max_turn = FoldTurn(spacing.fold_ratio);
  const std::vector<double> turned = TurningAt(s, kink, st);
  const double dy0 = c[1][0] - c[0][0], dz0 = c[1][1] - c[0][1];
  const double keel_turn =
      std::fabs(std::atan2(2.0 * dy0 * dz0, dy0 * dy0 - dz0 * dz0));  // mirror image → contour
  const bool prune =
      max_turn > 0.0 && !turned.empty() && std::isfinite(turned.back()) && std::isfinite(keel_turn);
  SortedCursor below_m(turned), above_m(turned), through_keel(turned);
  for (int m = 0; m <= Mt; ++m) {
    const Point mirror{-pt[m][0], pt[m][1]};  // pt[m]'s mirror image: d_mirror is its distance to pt[q]
    double thick2 = std::numeric_limits<double>::infinity();  // thick[m]² while it is a safe bound
    auto consider = [&](int q, bool mirrored) {
      if (!mirrored && q == m) return;  // along = 0: never across
      const double along = mirrored ? st[q] + st[m] : std::fabs(st[q] - st[m]);
      if (squares_ok && Squared(pt[q], mirrored ? mirror : pt[m]) >
                            std::min(std::min(reach2, along * along * inv_fold2), thick2) * kMargin)
        return;
      const double d = mirrored
                           ? std::hypot(pt[q][0] + pt[m][0], pt[q][1] - pt[m][1])  // arc through the keel
                           : std::hypot(pt[q][0] - pt[m][0], pt[q][1] - pt[m][1]);
      if (along > spacing.fold_ratio * d) {
        thick[m] = std::min(thick[m], d);
        thick2 = thick[m] > 1e-100 ? thick[m] * thick[m] : std::numeric_limits<double>::infinity();
      }
    };
    if (!prune) {
      for (int q = 0; q <= Mt; ++q) consider(q, false), consider(q, true);
      continue;
    }
    // Same side: K[q] < K[m] − max_turn (towards the keel) or K[q] > K[m] + max_turn (towards the waterline).
    const int below =
        below_m.FirstAbove(turned[m] - max_turn) - 1;  // a superset of the first range: 0 .. below
    for (int q = 0; q <= std::min(below + 1, Mt); ++q) consider(q, false);
    for (int q = above_m.FirstAbove(turned[m] + max_turn); q <= Mt; ++q) consider(q, false);
    // Through the keel: K[m] + keel turn + K[q] > max_turn.
    for (int q = through_keel.FirstAbove(max_turn - keel_turn - turned[m]) - 1; q <= Mt; ++q)
      if (q >= 0) consider(q, true);
  }
  std::vector<double> ends{S};  // grading targets: the waterline and every corner
  for (std::size_t k : corners) ends.push_back(s[k]);
  const double w = 0.25 * H;  // window of the curvature estimate
  for (int m = 0; m <= M; ++m) {
    double h = H;
    const double lo = std::max(0.0, sg[m] - w), hi = std::min(S, sg[m] + w);
    const int mlo = RoundHalfUp(lo / S * M), mhi = RoundHalfUp(hi / S * M);
    const double kappa = hi > lo ? (turn_at[mhi] - turn_at[mlo]) / (hi - lo) : 0.0;
    if (kappa > 0) h = std::min(h, spacing.max_turn_rad / kappa);
    const double x = sg[m] / S * Mt;
    const int k = std::min(static_cast<int>(x), Mt - 1);
    const double t = std::min(thick[k], thick[k + 1]);  // the thinner neighbour: a thin part is not missed
    if (std::isfinite(t)) h = std::min(h, spacing.thickness_fraction * t);
    for (double e : ends) h = std::min(h, spacing.end_spacing * H + spacing.grading * std::fabs(sg[m] - e));
    density[m] = 1.0 / std::max(h, 1e-9 * S);
  }
  std::vector<double> phi(M + 1, 0.0);  // cumulative panels-worth ∫ density ds
  for (int m = 1; m <= M; ++m) phi[m] = phi[m - 1] + 0.5 * (density[m] + density[m - 1]) * (sg[m] - sg[m - 1]);
  auto phi_at = [&](double si) {
    const double x = std::clamp(si / S * M, 0.0, static_cast<double>(M));
    const int m = std::min(static_cast<int>(x), M - 1);
    return phi[m] + (x - m) * (phi[m + 1] - phi[m]);
  };
  auto s_of_phi = [&](double p) {
    const int m = std::clamp(static_cast<int>(std::upper_bound(phi.begin(), phi.end(), p) - phi.begin()), 1, M);
    const double d = phi[m] - phi[m - 1];
    return sg[m - 1] + (d > 0 ? (p - phi[m - 1]) / d : 0.0) * (sg[m] - sg[m - 1]);
  };
  // Panels per corner-delimited segment in proportion to its share of ∫ density (largest remainder, at least
  // one each), then equal shares of ∫ density within each segment.
  std::vector<double> bounds{0.0};
  for (std::size_t k : corners) bounds.push_back(s[k]);
  bounds.push_back(S);
  const int nseg = static_cast<int>(bounds.size()) - 1;
  std::vector<double> share(nseg);
  std::vector<int> count(nseg, 1);
  const double total = phi.back();
  for (int g = 0; g < nseg; ++g) share[g] = (phi_at(bounds[g + 1]) - phi_at(bounds[g])) / total * nh;
  for (int left = nh - nseg; left > 0; --left) {
    int best = 0;
    for (int g = 1; g < nseg; ++g)
      if (share[g] - count[g] > share[best] - count[best]) best = g;
    ++count[best];
  }
  std::vector<double> node_s{0.0};
  for (int g = 0; g < nseg; ++g) {
    const double p0 = phi_at(bounds[g]), p1 = phi_at(bounds[g + 1]);
    for (int i = 1; i < count[g]; ++i) node_s.push_back(s_of_phi(p0 + (p1 - p0) * i / count[g]));
    node_s.push_back(bounds[g + 1]);
  }
  std::vector<Point> pts(nh + 1);
  for (int i = 0; i <= nh; ++i) pts[i] = at(node_s[i]);
  pts[0] = {0.0, c.front()[1]};
  pts[nh] = {c.back()[0], 0.0};
  // Turning of the contour strictly inside each panel (vertices on its end points, corners among them, are
  // the kinks between chords and stay out).
  std::vector<double> turn(nh, 0.0);
  const bool sorted_nodes = std::is_sorted(node_s.begin(), node_s.end());
  for (std::size_t k = 1; k + 1 < nv; ++k) {
    const double tol = 1e-9 * S;
    // With the end points in order only the panel whose span holds s[k] can hold it strictly inside.
    const int first =
        sorted_nodes
            ? std::clamp(
                  static_cast<int>(std::upper_bound(node_s.begin(), node_s.end(), s[k]) - node_s.begin()) - 1,
                  0, nh - 1)
            : 0;
    const int last = sorted_nodes ? first : nh - 1;
    for (int i = first; i <= last; ++i)
      if (s[k] > node_s[i] + tol && s[k] < node_s[i + 1] - tol) turn[i] += kink[k];
  }
  std::vector<Panel> panels;
  panels.reserve(n_panels);
  // Port side: waterline down to keel (y > 0).
  for (int i = nh; i > 0; --i)
    panels.push_back({y_centre_m + pts[i][0], pts[i][1], y_centre_m + pts[i - 1][0], pts[i - 1][1], turn[i - 1]});
  // Starboard side: keel up to waterline (y < 0).
  for (int i = 0; i < nh; ++i)
    panels.push_back({y_centre_m - pts[i][0], pts[i][1], y_centre_m - pts[i + 1][0], pts[i + 1][1], turn[i]});
  return panels;
}

}  // namespace hullopt::sk
