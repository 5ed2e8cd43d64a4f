#include "parametric_hull/section_geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hullopt::hull {
namespace {

// Largest ratio of neighbouring station spacings for which the uneven Simpson rule is used (its weights stay
// positive up to a ratio of 2 and mildly negative up to 4).
constexpr double kMaxStepRatio = 4.0;

// Normalised cumulative arc length of a contour (0 at the keel, 1 at the deck edge). A contour of zero length
// (a single point or repeated points) gets an even spacing so it can still be blended.
std::vector<double> ArcParameter(const Station& s) {
  const size_t n = s.y_m.size();
  std::vector<double> t(n, 0.0);
  for (size_t i = 1; i < n; ++i)
    t[i] = t[i - 1] + std::hypot(s.y_m[i] - s.y_m[i - 1], s.z_m[i] - s.z_m[i - 1]);
  const double total = n > 1 ? t[n - 1] : 0.0;
  for (size_t i = 0; i < n; ++i) t[i] = total > 0.0 ? t[i] / total : (n > 1 ? double(i) / (n - 1) : 0.0);
  return t;
}

// Point on the contour at normalised arc parameter u.
std::array<double, 2> PointAt(const Station& s, const std::vector<double>& t, double u) {
  const size_t n = t.size();
  if (n == 1 || u <= t[0]) return {s.y_m[0], s.z_m[0]};
  if (u >= t[n - 1]) return {s.y_m[n - 1], s.z_m[n - 1]};
  const size_t j = std::upper_bound(t.begin(), t.end(), u) - t.begin();  // t[j-1] <= u < t[j]
  const double dt = t[j] - t[j - 1];
  const double f = dt > 0.0 ? (u - t[j - 1]) / dt : 0.0;
  return {s.y_m[j - 1] + f * (s.y_m[j] - s.y_m[j - 1]), s.z_m[j - 1] + f * (s.z_m[j] - s.z_m[j - 1])};
}

}  // namespace

Station InterpolateStation(const Demihull& body, double x_m) {
  const auto& st = body.stations;
  if (st.empty()) throw std::invalid_argument("InterpolateStation: body '" + body.role + "' has no stations");
  Station out;
  out.x_m = x_m;
  if (x_m < st.front().x_m || x_m > st.back().x_m) return out;  // outside the body: dry, no points
  size_t j =
      std::upper_bound(st.begin(), st.end(), x_m, [](double x, const Station& s) { return x < s.x_m; }) -
      st.begin();        // st[j-1].x <= x < st[j].x
  if (j == st.size()) {  // x == last station
    out = st.back();
    out.x_m = x_m;
    return out;
  }
  const Station& a = st[j - 1];
  const Station& b = st[j];
  const double f = (x_m - a.x_m) / (b.x_m - a.x_m);
  if (f == 0.0 || b.y_m.empty()) {
    out = a;
    out.x_m = x_m;
    return out;
  }
  if (a.y_m.empty()) {
    out = b;
    out.x_m = x_m;
    return out;
  }
  const std::vector<double> ta = ArcParameter(a), tb = ArcParameter(b);
  std::vector<double> u(ta);
  u.insert(u.end(), tb.begin(), tb.end());
  std::sort(u.begin(), u.end());
  u.erase(std::unique(u.begin(), u.end(), [](double p, double q) { return std::fabs(p - q) < 1e-12; }),
          u.end());
  out.y_m.reserve(u.size());
  out.z_m.reserve(u.size());
  double z_prev = -INFINITY;
  for (double ui : u) {
    const auto pa = PointAt(a, ta, ui), pb = PointAt(b, tb, ui);
    const double z = std::max(z_prev, (1.0 - f) * pa[1] + f * pb[1]);  // guards round-off only
    out.y_m.push_back(std::max(0.0, (1.0 - f) * pa[0] + f * pb[0]));
    out.z_m.push_back(z);
    z_prev = z;
  }
  return out;
}

std::vector<std::array<double, 2>> WettedContour(const Station& s, double draught_m) {
  std::vector<std::array<double, 2>> out;
  const size_t n = std::min(s.y_m.size(), s.z_m.size());
  if (n == 0 || s.z_m[0] > draught_m) return out;
  for (size_t i = 0; i < n; ++i) {
    if (s.z_m[i] <= draught_m) {
      out.push_back({s.y_m[i], s.z_m[i]});
      continue;
    }
    // First point above the waterline: add the crossing on segment i-1 -> i, unless the previous point is on
    // it.
    const double z0 = s.z_m[i - 1], z1 = s.z_m[i];
    if (z0 < draught_m) {
      const double f = (draught_m - z0) / (z1 - z0);
      out.push_back({s.y_m[i - 1] + f * (s.y_m[i] - s.y_m[i - 1]), draught_m});
    }
    break;
  }
  return out;
}

SectionProperties ComputeSectionProperties(const Station& s, double draught_m) {
  SectionProperties p;
  const auto c = WettedContour(s, draught_m);
  if (c.empty()) return p;
  p.wet = true;
  p.keel_z_m = c.front()[1];
  for (const auto& q : c) p.max_half_breadth_m = std::max(p.max_half_breadth_m, q[0]);
  for (size_t i = 1; i < c.size(); ++i) {
    const double y0 = c[i - 1][0], z0 = c[i - 1][1], y1 = c[i][0], z1 = c[i][1];
    const double dz = z1 - z0;
    // Region between the centreline and the contour: dA = y dz, exact for a linear segment.
    p.area_m2 += 0.5 * (y0 + y1) * dz;
    p.moment_z_m3 += dz * (y0 * z0 / 3.0 + (y0 * z1 + y1 * z0) / 6.0 + y1 * z1 / 3.0);
    p.girth_m += std::hypot(y1 - y0, dz);
  }
  // Waterline half-breadth only if the contour actually reaches the waterline.
  if (c.back()[1] >= draught_m) p.waterline_half_breadth_m = c.back()[0];
  return p;
}

std::vector<double> LongitudinalWeights(const std::vector<double>& x) {
  const size_t n = x.size();
  std::vector<double> w(n, 0.0);
  for (size_t i = 1; i < n; ++i)
    if (!(x[i] > x[i - 1]))
      throw std::invalid_argument("LongitudinalWeights: station x must be strictly increasing (x[" +
                                  std::to_string(i) + "] = " + std::to_string(x[i]) + ")");
  if (n < 2) return w;
  if (n == 2) {
    w[0] = w[1] = 0.5 * (x[1] - x[0]);
    return w;
  }
  const size_t intervals = n - 1;
  const size_t paired = intervals % 2 == 0 ? intervals : intervals - 1;
  // Very uneven neighbours (e.g. an end station added next to a grid station) would give large negative
  // Simpson weights; there the pair falls back to the trapezoid rule.
  const auto uneven = [](double h0, double h1) { return h0 > kMaxStepRatio * h1 || h1 > kMaxStepRatio * h0; };
  for (size_t i = 0; i + 2 <= paired; i += 2) {
    const double h0 = x[i + 1] - x[i], h1 = x[i + 2] - x[i + 1], hs = h0 + h1;
    if (uneven(h0, h1)) {
      w[i] += 0.5 * h0;
      w[i + 1] += 0.5 * (h0 + h1);
      w[i + 2] += 0.5 * h1;
      continue;
    }
    w[i] += hs / 6.0 * (2.0 - h1 / h0);
    w[i + 1] += hs * hs * hs / (6.0 * h0 * h1);
    w[i + 2] += hs / 6.0 * (2.0 - h0 / h1);
  }
  if (paired < intervals) {  // last interval by the quadratic through the last three points
    const double h0 = x[n - 2] - x[n - 3], h1 = x[n - 1] - x[n - 2];
    if (uneven(h0, h1)) {
      w[n - 2] += 0.5 * h1;
      w[n - 1] += 0.5 * h1;
      return w;
    }
    w[n - 1] += h1 * (2.0 * h1 + 3.0 * h0) / (6.0 * (h0 + h1));
    w[n - 2] += h1 * (h1 + 3.0 * h0) / (6.0 * h0);
    w[n - 3] -= h1 * h1 * h1 / (6.0 * h0 * (h0 + h1));
  }
  return w;
}

HullForm Resample(const HullForm& hull, int stations) {
  if (stations < 2)
    throw std::invalid_argument("Resample: need at least 2 stations, got " + std::to_string(stations));
  if (hull.bodies.empty() || hull.bodies[0].stations.empty())
    throw std::invalid_argument("Resample: the hull has no main body with stations");
  const double x0 = hull.bodies[0].stations.front().x_m, x1 = hull.bodies[0].stations.back().x_m;
  std::vector<double> grid(stations);
  for (int i = 0; i < stations; ++i) grid[i] = x0 + (x1 - x0) * i / (stations - 1);
  grid.back() = x1;
  HullForm out = hull;
  for (size_t b = 0; b < hull.bodies.size(); ++b) {
    const Demihull& body = hull.bodies[b];
    Demihull& nb = out.bodies[b];
    nb.stations.clear();
    if (body.stations.empty()) continue;
    const double b0 = body.stations.front().x_m, b1 = body.stations.back().x_m;
    const double tol = 1e-9 * std::max(1.0, std::fabs(x1 - x0));
    std::vector<double> xs;
    for (double x : grid)
      if (x >= b0 - tol && x <= b1 + tol) xs.push_back(std::min(std::max(x, b0), b1));
    if (xs.empty() || xs.front() - b0 > tol) xs.insert(xs.begin(), b0);
    if (b1 - xs.back() > tol) xs.push_back(b1);
    for (double x : xs) nb.stations.push_back(InterpolateStation(body, x));
  }
  return out;
}

}  // namespace hullopt::hull
