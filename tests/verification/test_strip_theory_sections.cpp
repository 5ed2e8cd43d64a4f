// Strip theory on 2D frequency-domain sections: the reciprocity row of a section reproduces the panel solver's
// own heave added mass and damping (two routes through the solver), and strip theory on a real hull keeps the
// long-wave limits.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>

#include "seakeeping/sections/frequency_domain_section.h"
#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/sections/section_shapes.h"
#include "seakeeping/strip/strip_geometry.h"
#include "seakeeping/motions/strip_theory_stf.h"
#include "support/delft372_hull.h"
#include "support/ursell_semicircle.h"

namespace sk = hullopt::sk;

TEST_CASE("section row: R·n_z = −(iω a33 + b33)", "[stf][sections]") {
  sk::StripKernel g;
  g.rho_kg_m3 = 1025.0;
  g.g_m_s2 = 9.81;
  g.panels = {sk::PanelSymmetricSection(sk::SemicircleContour(1.0, 400), 24)};
  const auto rows = sk::FrequencyDomainSectionRows(g, 24);
  for (double w : {0.5, 1.5, 3.0}) {
    const auto r = rows(0, w);
    std::complex<double> rn = 0;
    for (std::size_t i = 0; i < g.panels[0].size(); ++i) rn += r[i] * g.panels[0][i].Normal()[1];
    sk::FrequencyDomainOptions o;
    o.rho_kg_m3 = 1025.0;
    const auto h = sk::SolveSectionFrequencyDomain(g.panels, w, o);
    const std::complex<double> expect(-h.b33(), -w * h.a33());
    // The row integrates ψ at panel midpoints (one-point rule); the solver's a33/b33 use the same potentials:
    // agreement to the midpoint-quadrature level of the potential, 1e-6 relative.
    CHECK(std::abs(rn - expect) < 1e-6 * std::abs(expect));
  }
}

TEST_CASE("section rows, direct formulation: the solver's a33 and b33, and Ursell's at 14 panels",
          "[stf][sections][direct]") {
  // The same reciprocity row on the direct formulation's potential, then against Ursell's multipole solution
  // (independent of the panel solvers) at the strips' default 14 panels: a33 within 1 %, b33 within 2 % up
  // to νR = 1 and 4 % above (the section solver's own tolerances for this formulation, where 7 panels a side
  // resolve the waterline region of depth 1/ν with two or three panels; verification_frequency_domain_section).
  constexpr double kRho = 1025.0, kG = 9.81, kR = 1.0;
  constexpr double kTolRow = 1e-6, kTolA = 0.01, kTolB = 0.02, kTolBHigh = 0.04;
  sk::StripKernel g;
  g.rho_kg_m3 = kRho;
  g.g_m_s2 = kG;
  g.panels = {sk::PanelSymmetricSection(sk::SemicircleContour(kR, 4000), 14)};
  const auto rows = sk::FrequencyDomainSectionRows(g, 14, true, sk::SectionFormulation::kDirect);
  const double m0 = kRho * M_PI * kR * kR / 2;
  for (double nuR : {0.25, 0.5, 1.0, 2.0, 3.0}) {
    const double w = std::sqrt(nuR * kG / kR);
    const auto r = rows(0, w);
    std::complex<double> rn = 0;
    for (std::size_t i = 0; i < g.panels[0].size(); ++i) rn += r[i] * g.panels[0][i].Normal()[1];
    sk::FrequencyDomainOptions o;
    o.rho_kg_m3 = kRho;
    o.g_m_s2 = kG;
    o.formulation = sk::SectionFormulation::kDirect;
    const auto h = sk::SolveSectionFrequencyDomain(g.panels, w, o);
    const std::complex<double> expect(-h.b33(), -w * h.a33());
    INFO("nuR = " << nuR);
    CHECK(std::abs(rn - expect) < kTolRow * std::abs(expect));
    const auto u = hullopt::testing::UrsellSemicircleHeave(nuR);
    const double a = -rn.imag() / w / m0, b = -rn.real() / (m0 * w);
    CHECK(std::fabs(a / u.a33 - 1) <= kTolA);
    CHECK(std::fabs(b / u.b33 - 1) <= (nuR <= 1.0 ? kTolB : kTolBHigh));
  }
}

TEST_CASE("section rows without interaction: each body alone, mirror bodies shared", "[stf][sections]") {
  // An asymmetric polygon at y ≈ +2 and its mirror image about y = 0 (one solver, read in reverse panel
  // order), and a rectangle at y = 5 (its own), each solved alone: the rows equal iωρ ψ_i l_i with ψ from
  // SolveSectionFrequencyDomain on that body by itself, to rounding (1e-11 of the largest entry: the same
  // discrete problem, see the heave solver test of verification_frequency_domain_section).
  constexpr double kTolRounding = 1e-11;
  // Port waterline → keel → starboard waterline, 4 panels per edge: 16 panels.
  const std::vector<std::array<double, 2>> corners = {{3.0, 0.0}, {2.8, -0.6}, {2.0, -0.8}, {1.5, -0.5}, {1.3, 0.0}};
  std::vector<sk::Panel> poly, mirror;
  for (std::size_t e = 0; e + 1 < corners.size(); ++e)
    for (int q = 0; q < 4; ++q) {
      const auto& a = corners[e];
      const auto& b = corners[e + 1];
      poly.push_back({a[0] + (b[0] - a[0]) * q / 4, a[1] + (b[1] - a[1]) * q / 4, a[0] + (b[0] - a[0]) * (q + 1) / 4,
                      a[1] + (b[1] - a[1]) * (q + 1) / 4});
    }
  for (auto it = poly.rbegin(); it != poly.rend(); ++it) mirror.push_back({-it->y2, it->z2, -it->y1, it->z1});
  const std::vector<std::vector<sk::Panel>> bodies = {
      poly, sk::PanelSymmetricSection(sk::RectangleContour(1.2, 0.5), 16, 5.0), mirror};
  sk::StripKernel g;
  g.rho_kg_m3 = 1025.0;
  g.g_m_s2 = 9.81;
  g.panels.emplace_back();
  for (const auto& b : bodies) g.panels[0].insert(g.panels[0].end(), b.begin(), b.end());
  const auto rows = sk::FrequencyDomainSectionRows(g, 16, false);
  sk::FrequencyDomainOptions o;
  o.rho_kg_m3 = 1025.0;
  for (double w : {0.7, 2.0}) {
    const Eigen::RowVectorXcd r = rows(0, w);
    REQUIRE(r.size() == 48);
    Eigen::RowVectorXcd expect(48);
    for (int b = 0; b < 3; ++b) {
      const auto h = sk::SolveSectionFrequencyDomain({bodies[b]}, w, o);
      for (int k = 0; k < 16; ++k)
        expect[16 * b + k] =
            std::complex<double>(0.0, w * 1025.0) * h.radiation_potential(k, 1) * bodies[b][k].Length();
    }
    CHECK((r - expect).cwiseAbs().maxCoeff() <= kTolRounding * expect.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("strip theory on Delft 372: long-wave limits", "[stf][delft372]") {
  sk::StripGeometryOptions geo;
  geo.sections = 20;
  geo.panels = 8;
  const double U = 0.75 * std::sqrt(9.81 * 3.0);
  const auto g = sk::StripKernelGeometry(hullopt::testing::Delft372Hull(HULLOPT_SOURCE_DIR), geo, U, 1000.0, 9.81);
  sk::MotionOptions mo;
  mo.damping_cs = 0.0;
  const sk::HeadSeaShipModel model(g, hullopt::testing::Delft372Mass(), mo);
  const auto r = sk::SolveStripTheoryRaos(model, {0.05}, sk::FrequencyDomainSectionRows(g, geo.panels));
  constexpr double kLimitTol = 0.02;  // long-wave limit: 2%
  CHECK(std::abs(std::abs(r.heave[0]) - 1.0) < kLimitTol);
  CHECK(std::abs(std::abs(r.pitch[0]) - 1.0) < kLimitTol);
}
