// Wigley hull y = B/2 (1 - (2x/L)^2)(1 - (z/T)^2): hydrostatics against closed forms.
//   volume 4LBT/9, waterplane area 2LB/3, I_L about midships (= LCF) B L^3/30, I_T 4 B^3 L/105, KB 5T/8.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "io/formats/stl_reader.h"
#include "parametric_hull/hydrostatics.h"
#include "parametric_hull/section_geometry.h"

using namespace hullopt::hull;

namespace {
constexpr double kL = 4.0, kB = 0.4, kT = 0.25;
// Required: closed forms to 1e-4 relative. With 101 points per section the polyline's
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

namespace {
// Triangulated Wigley surface, both sides, open at the deck: the analytic offsets' grid, each quad split in
// two.
hullopt::io::StlMesh WigleyMesh() {
  const HullForm h = WigleyOffsets();
  const auto& st = h.bodies[0].stations;
  hullopt::io::StlMesh mesh;
  for (size_t i = 0; i + 1 < st.size(); ++i)
    for (size_t k = 0; k + 1 < st[i].y_m.size(); ++k)
      for (double side : {1.0, -1.0}) {
        const std::array<double, 3> a{st[i].x_m, side * st[i].y_m[k], st[i].z_m[k]},
            b{st[i + 1].x_m, side * st[i + 1].y_m[k], st[i + 1].z_m[k]},
            c{st[i + 1].x_m, side * st[i + 1].y_m[k + 1], st[i + 1].z_m[k + 1]},
            d{st[i].x_m, side * st[i].y_m[k + 1], st[i].z_m[k + 1]};
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
      }
  return mesh;
}

void CheckWigleyClosedForms(const HullForm& h) {
  const Hydrostatics hs = ComputeHydrostatics(h, 1000.0);
  CHECK(hs.volume_m3 == Approx(4.0 * kL * kB * kT / 9.0).epsilon(kClosedFormTol));
  CHECK(hs.awp_m2 == Approx(2.0 * kL * kB / 3.0).epsilon(kClosedFormTol));
  CHECK(hs.i_l_m4 == Approx(kB * kL * kL * kL / 30.0).epsilon(kClosedFormTol));
}

HullForm FromStl(const std::string& path) {
  HullForm h;
  h.draught_m = kT;
  h.bodies = {hullopt::io::SliceStl(hullopt::io::ReadStl(path), kStations, kT, path)};
  return h;
}
}  // namespace

TEST_CASE("Wigley hull from a binary STL matches the closed forms", "[wigley][stl]") {
  // Binary STL stores single precision: 6e-8 relative, far below the tolerance.
  const std::string path = HULLOPT_BINARY_DIR "/wigley_test.stl";
  hullopt::io::WriteBinaryStl(path, WigleyMesh());
  const HullForm h = FromStl(path);
  REQUIRE(h.bodies[0].stations.size() == size_t(kStations));
  CheckWigleyClosedForms(h);
  std::remove(path.c_str());
}

TEST_CASE("Wigley hull from an ASCII STL matches the closed forms", "[wigley][stl]") {
  const std::string path = HULLOPT_BINARY_DIR "/wigley_test_ascii.stl";
  {
    std::ofstream out(path);
    out.precision(12);
    out << "solid wigley\n";
    for (const auto& t : WigleyMesh().triangles) {
      out << "  facet normal 0 0 0\n    outer loop\n";
      for (const auto& v : t) out << "      vertex " << v[0] << ' ' << v[1] << ' ' << v[2] << "\n";
      out << "    endloop\n  endfacet\n";
    }
    out << "endsolid wigley\n";
  }
  CheckWigleyClosedForms(FromStl(path));
  std::remove(path.c_str());
}
