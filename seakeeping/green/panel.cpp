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

Point PointAt(const std::vector<Point>& c, const std::vector<double>& s, double si) {
  const std::size_t nv = c.size();
  const std::size_t k = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), si) - s.begin()), 1, nv - 1);
  const double seg = s[k] - s[k - 1];
  const double f = seg > 0 ? std::clamp((si - s[k - 1]) / seg, 0.0, 1.0) : 0.0;
  return Point{c[k - 1][0] + f * (c[k][0] - c[k - 1][0]), c[k - 1][1] + f * (c[k][1] - c[k - 1][1])};
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
  for (int m = 0; m <= M; ++m) p[m] = PointAt(c, s, S * m / M);
  std::vector<std::array<double, 2>> cuts;  // [s_a, s_b] removed
  for (int m = 0; m <= M; ++m) {
    if (!cuts.empty() && S * m / M <= cuts.back()[1]) continue;
    int partner = -1;
    for (int q = M; q > m; --q) {  // the farthest point across: the whole fin goes
      const double d = std::hypot(p[q][0] - p[m][0], p[q][1] - p[m][1]);
      if (d < limit && S * (q - m) / M > fold_ratio * std::max(d, 1e-300)) {
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
        out.push_back(PointAt(c, s, cuts[g][0]));
        out.push_back(PointAt(c, s, cuts[g][1]));
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
    if (std::hypot(raw[i][0] - c.back()[0], raw[i][1] - c.back()[1]) > 1e-12 * scale) c.push_back(raw[i]);
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
  auto at = [&](double si) {
    const std::size_t k = std::clamp<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), si) - s.begin()), 1, nv - 1);
    const double seg = s[k] - s[k - 1];
    const double f = seg > 0 ? std::clamp((si - s[k - 1]) / seg, 0.0, 1.0) : 0.0;
    return Point{c[k - 1][0] + f * (c[k][0] - c[k - 1][0]), c[k - 1][1] + f * (c[k][1] - c[k - 1][1])};
  };
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
  // Smooth turning |Θ|(s) at the grid points, cumulative: each non-corner vertex's |kink| spread linearly over
  // the halves of its two segments.
  std::vector<double> turn_at(M + 1, 0.0);
  for (std::size_t k = 1; k + 1 < nv; ++k) {
    if (is_corner[k] || kink[k] == 0.0) continue;
    const double a = 0.5 * (s[k - 1] + s[k]), b = 0.5 * (s[k] + s[k + 1]);
    const int m0 = std::clamp(static_cast<int>(std::floor(a / S * M)), 0, M);
    for (int m = m0; m <= M; ++m) turn_at[m] += std::fabs(kink[k]) * std::clamp((sg[m] - a) / (b - a), 0.0, 1.0);
  }
  // Local thickness on a coarser grid: the nearest contour point (of the half contour or its mirror image)
  // that is much farther along the contour than in space lies across a thin part.
  const int Mt = std::max(100, 10 * nh);
  std::vector<Point> pt(Mt + 1);
  std::vector<double> st(Mt + 1), thick(Mt + 1, std::numeric_limits<double>::infinity());
  for (int m = 0; m <= Mt; ++m) st[m] = S * m / Mt, pt[m] = at(st[m]);
  for (int m = 0; m <= Mt; ++m) {
    for (int q = 0; q <= Mt; ++q) {
      const double d_same = std::hypot(pt[q][0] - pt[m][0], pt[q][1] - pt[m][1]);
      if (std::fabs(st[q] - st[m]) > spacing.fold_ratio * d_same) thick[m] = std::min(thick[m], d_same);
      const double d_mirror = std::hypot(pt[q][0] + pt[m][0], pt[q][1] - pt[m][1]);  // arc through the keel
      if (st[q] + st[m] > spacing.fold_ratio * d_mirror) thick[m] = std::min(thick[m], d_mirror);
    }
  }
  std::vector<double> ends{S};  // grading targets: the waterline and every corner
  for (std::size_t k : corners) ends.push_back(s[k]);
  const double w = 0.25 * H;  // window of the curvature estimate
  for (int m = 0; m <= M; ++m) {
    double h = H;
    const double lo = std::max(0.0, sg[m] - w), hi = std::min(S, sg[m] + w);
    const int mlo = static_cast<int>(std::lround(lo / S * M)), mhi = static_cast<int>(std::lround(hi / S * M));
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
  for (std::size_t k = 1; k + 1 < nv; ++k) {
    const double tol = 1e-9 * S;
    for (int i = 0; i < nh; ++i)
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
