// Wigley hull y = B/2 (1 - (2x/L)^2)(1 - (z/T)^2): hydrostatics against closed forms.
//   volume 4LBT/9, waterplane area 2LB/3, I_L about midships (= LCF) B L^3/30, I_T 4 B^3 L/105, KB 5T/8.
#include <catch2/catch.hpp>
#include <cmath>

#include "parametric_hull/hydrostatics.h"
#include "parametric_hull/section_geometry.h"

using namespace hullopt::hull;

namespace {
constexpr double kL = 4.0, kB = 0.4, kT = 0.25;
// Required by the issue: closed forms to 1e-4 relative. With 101 points per section the polyline's
// trapezoid error in z is h^2/4 = 2.5e-5 relative; Simpson in x is exact for the quadratic area curve and
// 6e-6 for the quartic I_L integrand with 41 stations.
constexpr double kClosedFormTol = 1e-4;
constexpr int kStations = 41, kPoints = 101;

HullForm WigleyOffsets() {
  HullForm h;
  h.type = "offsets";
  h.draught_m = kT;
  h.length_m = kL;
  Demihull d;
  d.role = "main";
  for (int i = 0; i < kStations; ++i) {
    Station s;
    s.x_m = kL * i / (kStations - 1);
    const double xi = 2.0 * s.x_m / kL - 1.0;
    for (int k = 0; k < kPoints; ++k) {
      const double z = kT * k / (kPoints - 1);
      const double zeta = (kT - z) / kT;
      s.y_m.push_back(0.5 * kB * (1 - xi * xi) * (1 - zeta * zeta));
      s.z_m.push_back(z);
    }
    s.y_m.push_back(s.y_m.back());  // wall-sided freeboard above the waterline
    s.z_m.push_back(1.5 * kT);
    d.stations.push_back(s);
  }
  h.bodies = {d};
  return h;
}
}  // namespace

TEST_CASE("Wigley hull from analytic offsets matches the closed forms", "[wigley][hydrostatics]") {
  const HullForm h = WigleyOffsets();
  const Hydrostatics hs = ComputeHydrostatics(h, 1000.0);
  CHECK(hs.volume_m3 == Approx(4.0 * kL * kB * kT / 9.0).epsilon(kClosedFormTol));
  CHECK(hs.awp_m2 == Approx(2.0 * kL * kB / 3.0).epsilon(kClosedFormTol));
  CHECK(hs.i_l_m4 == Approx(kB * kL * kL * kL / 30.0).epsilon(kClosedFormTol));
  CHECK(hs.i_t_m4 == Approx(4.0 * kB * kB * kB * kL / 105.0).epsilon(kClosedFormTol));
  CHECK(hs.vcb_m == Approx(5.0 * kT / 8.0).epsilon(kClosedFormTol));
  CHECK(hs.Cb == Approx(4.0 / 9.0).epsilon(kClosedFormTol));
  CHECK(hs.Cwp == Approx(2.0 / 3.0).epsilon(kClosedFormTol));
  CHECK(hs.Cm == Approx(2.0 / 3.0).epsilon(kClosedFormTol));
  CHECK(hs.LCB_pct_L == Approx(0.0).margin(kClosedFormTol));
  CHECK(hs.L_m == kL);
  CHECK(hs.B_m == Approx(kB));
}

TEST_CASE("Wigley hull resampled to 21 stations keeps volume and waterplane", "[wigley][geometry]") {
  // Station shapes are similar (y scales with 1 - xi^2), so blending two of them by arc length is not exact
  // in between; but the resampled stations coincide with original ones at every second grid point.
  const HullForm r = Resample(WigleyOffsets(), 21);
  const Hydrostatics hs = ComputeHydrostatics(r, 1000.0);
  CHECK(r.bodies[0].stations.size() == 21);
  CHECK(hs.volume_m3 == Approx(4.0 * kL * kB * kT / 9.0).epsilon(kClosedFormTol));
  CHECK(hs.awp_m2 == Approx(2.0 * kL * kB / 3.0).epsilon(kClosedFormTol));
}
