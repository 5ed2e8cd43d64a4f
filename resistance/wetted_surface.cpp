#include "resistance/wetted_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace hullopt::res {
namespace {

using P3 = std::array<double, 3>;

// Normalised arc parameter of a station's full contour (keel 0, deck edge 1), as the hull's own
// interpolation between stations uses it (parametric_hull/section_geometry.h).
std::vector<double> Arc(const hull::Station& s) {
  const size_t n = s.y_m.size();
  std::vector<double> t(n, 0.0);
  for (size_t i = 1; i < n; ++i) t[i] = t[i - 1] + std::hypot(s.y_m[i] - s.y_m[i - 1], s.z_m[i] - s.z_m[i - 1]);
  const double total = n > 1 ? t[n - 1] : 0.0;
  for (size_t i = 0; i < n; ++i) t[i] = total > 0.0 ? t[i] / total : (n > 1 ? double(i) / (n - 1) : 0.0);
  return t;
}

P3 At(const hull::Station& s, const std::vector<double>& t, double u) {
  const size_t n = t.size();
  if (n == 1 || u <= t[0]) return {s.x_m, s.y_m[0], s.z_m[0]};
  if (u >= t[n - 1]) return {s.x_m, s.y_m[n - 1], s.z_m[n - 1]};
  const size_t j = std::upper_bound(t.begin(), t.end(), u) - t.begin();
  const double dt = t[j] - t[j - 1], f = dt > 0.0 ? (u - t[j - 1]) / dt : 0.0;
  return {s.x_m, s.y_m[j - 1] + f * (s.y_m[j] - s.y_m[j - 1]), s.z_m[j - 1] + f * (s.z_m[j] - s.z_m[j - 1])};
}

// Area of the part z <= zc of triangle (a, b, c): Sutherland–Hodgman against one plane, then a fan.
double ClippedTriangleArea(const P3& a, const P3& b, const P3& c, double zc) {
  const P3 in[3] = {a, b, c};
  P3 poly[4];
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    const P3& p = in[i];
    const P3& q = in[(i + 1) % 3];
    const bool pin = p[2] <= zc, qin = q[2] <= zc;
    if (pin) poly[n++] = p;
    if (pin != qin) {
      const double f = (zc - p[2]) / (q[2] - p[2]);
      poly[n++] = {p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1]), zc};
    }
  }
  double area = 0.0;
  for (int i = 1; i + 1 < n; ++i) {
    const P3 u{poly[i][0] - poly[0][0], poly[i][1] - poly[0][1], poly[i][2] - poly[0][2]};
    const P3 v{poly[i + 1][0] - poly[0][0], poly[i + 1][1] - poly[0][1], poly[i + 1][2] - poly[0][2]};
    const double cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
    area += 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
  }
  return area;
}

}  // namespace

double BodyWettedSurface(const hull::Demihull& body, double draught_m, int points) {
  if (points < 2) throw std::invalid_argument("BodyWettedSurface: points must be >= 2");
  const auto& st = body.stations;
  double area = 0.0;
  for (size_t i = 0; i + 1 < st.size(); ++i) {
    const hull::Station& a = st[i];
    const hull::Station& b = st[i + 1];
    if (a.y_m.empty() || b.y_m.empty()) continue;
    const std::vector<double> ta = Arc(a), tb = Arc(b);
    std::vector<double> u(ta);
    u.insert(u.end(), tb.begin(), tb.end());
    for (int k = 0; k < points; ++k) u.push_back(double(k) / (points - 1));
    std::sort(u.begin(), u.end());
    u.erase(std::unique(u.begin(), u.end(), [](double p, double q) { return std::fabs(p - q) < 1e-12; }), u.end());
    for (size_t k = 0; k + 1 < u.size(); ++k) {
      const P3 a0 = At(a, ta, u[k]), a1 = At(a, ta, u[k + 1]), b0 = At(b, tb, u[k]), b1 = At(b, tb, u[k + 1]);
      area += ClippedTriangleArea(a0, b0, b1, draught_m) + ClippedTriangleArea(a0, b1, a1, draught_m);
    }
  }
  return 2.0 * area;  // both sides of the body's centreline
}

double WettedSurface(const hull::HullForm& hull, int points) {
  double s = 0.0;
  for (const auto& b : hull.bodies)
    s += (b.y_centre_m > 0.0 ? 2.0 : 1.0) * BodyWettedSurface(b, hull.draught_m, points);
  return s;
}

}  // namespace hullopt::res
