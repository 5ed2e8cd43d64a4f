// Rankine source panel closed forms against direct numerical quadrature of (1/2π)∫ ln r ds and its gradient,
// the +1/2 self term, and the flux theorem (a closed contour of unit-density panels emits its girth).
#include <catch2/catch.hpp>
#include <cmath>

#include "seakeeping/green/rankine_panel.h"

using hullopt::sk::Panel;

namespace {
// Composite Gauss–Legendre (many sub-intervals) of f(s) over the panel: an independent check of the closed form.
template <class F>
double Quad(const Panel& p, F f) {
  const int n_sub = 4000;
  const double g = 0.5 / std::sqrt(3.0);
  const double L = p.Length();
  double sum = 0;
  for (int k = 0; k < n_sub; ++k) {
    for (double xi : {0.5 - g, 0.5 + g}) {
      const double t = (k + xi) / n_sub;
      sum += f(p.y1 + t * (p.y2 - p.y1), p.z1 + t * (p.z2 - p.z1)) * 0.5 * L / n_sub;
    }
  }
  return sum;
}
// Field points one panel length or more away: quadrature converges to ~1e-12, so 1e-9 tests the closed form.
constexpr double kTolFar = 1e-9;
}  // namespace

TEST_CASE("Rankine panel potential and velocity match quadrature", "[rankine]") {
  const Panel p{0.3, -0.2, -0.1, -0.9};
  for (auto [y, z] : {std::pair{1.5, -0.4}, {-0.8, -1.7}, {0.2, -2.5}, {2.0, -0.05}}) {
    const auto inf = hullopt::sk::RankinePanelInfluence(p, y, z);
    const double phi = Quad(p, [&](double a, double b) { return std::log(std::hypot(y - a, z - b)) / (2 * M_PI); });
    const double vy = Quad(p, [&](double a, double b) {
      return (y - a) / ((y - a) * (y - a) + (z - b) * (z - b)) / (2 * M_PI);
    });
    const double vz = Quad(p, [&](double a, double b) {
      return (z - b) / ((y - a) * (y - a) + (z - b) * (z - b)) / (2 * M_PI);
    });
    CHECK(inf.phi == Approx(phi).epsilon(kTolFar));
    CHECK(inf.vy == Approx(vy).margin(kTolFar));
    CHECK(inf.vz == Approx(vz).margin(kTolFar));
    const auto img = hullopt::sk::ImagePanelInfluence(p, y, z);
    const double phi_img =
        Quad(p, [&](double a, double b) { return std::log(std::hypot(y - a, z + b)) / (2 * M_PI); });
    CHECK(img.phi == Approx(phi_img).epsilon(kTolFar));
  }
}

TEST_CASE("self influence: normal velocity +1/2 at the panel midpoint", "[rankine]") {
  const Panel p{0.4, -0.1, 0.1, -0.5};
  const auto n = p.Normal();
  const auto inf = hullopt::sk::RankinePanelInfluence(p, p.MidY(), p.MidZ());
  CHECK(inf.vy * n[0] + inf.vz * n[1] == Approx(0.5).margin(1e-14));
  // Potential at the midpoint: (L/2π)(ln(L/2) − 1), the closed form of ∫ ln|s| ds over [−L/2, L/2].
  const double L = p.Length();
  CHECK(inf.phi == Approx(L / (2 * M_PI) * (std::log(L / 2) - 1)).epsilon(1e-13));
}

namespace {
// Outward flux through a regular n-gon of unit-density panels, sampled at the panel midpoints.
double PolygonFlux(int n, double* perimeter) {
  std::vector<Panel> ps;
  for (int i = 0; i < n; ++i) {
    const double a1 = -2 * M_PI * i / n, a2 = -2 * M_PI * (i + 1) / n;  // clockwise: normals point outwards
    ps.push_back({std::cos(a1), -3 + std::sin(a1), std::cos(a2), -3 + std::sin(a2)});
  }
  double flux = 0;
  *perimeter = 0;
  for (const auto& pi : ps) {
    const auto nn = pi.Normal();
    double vn = 0;
    for (const auto& pj : ps) {
      const auto inf = hullopt::sk::RankinePanelInfluence(pj, pi.MidY(), pi.MidZ());
      vn += inf.vy * nn[0] + inf.vz * nn[1];
    }
    flux += vn * pi.Length();
    *perimeter += pi.Length();
  }
  return flux;
}
}  // namespace

TEST_CASE("flux of a closed polygon of unit-density panels converges to its perimeter", "[rankine]") {
  // Gauss: the outward flux equals the total source output (the perimeter). Midpoint sampling of a velocity
  // with log singularities at the vertices converges at first order: the error must halve per doubling.
  double p1 = 0, p2 = 0;
  const double e1 = PolygonFlux(96, &p1) / p1 - 1;
  const double e2 = PolygonFlux(192, &p2) / p2 - 1;
  constexpr double kTolFirstOrder192 = 5e-3;  // 1st-order error at 192 panels is ~3.6e-3
  CHECK(std::fabs(e2) < kTolFirstOrder192);
  CHECK(e1 / e2 == Approx(2.0).epsilon(0.05));
}
