// Strip theory on 2D frequency-domain sections: the reciprocity row of a section reproduces the panel solver's
// own heave added mass and damping (two routes through the solver), and strip theory on a real hull keeps the
// long-wave limits.
#include <catch2/catch.hpp>
#include <cmath>

#include "seakeeping/sections/frequency_domain_section.h"
#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/sections/section_shapes.h"
#include "seakeeping/strip/strip_geometry.h"
#include "seakeeping/motions/strip_theory_stf.h"
#include "support/delft372_hull.h"

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
