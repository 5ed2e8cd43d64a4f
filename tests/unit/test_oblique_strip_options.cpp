// Input checks of the oblique-sea strip theory (seakeeping/motions/oblique_strip_theory.h): options
// and mass properties name the field and rule; impossible requests throw std::invalid_argument.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "seakeeping/motions/oblique_strip_theory.h"

using namespace hullopt;

namespace {
sk::ObliqueMassProperties Mass() {
  sk::ObliqueMassProperties m;
  m.mass_kg = 10.0;
  m.inertia_kg_m2.diagonal() << 1.0, 2.0, 2.0;
  return m;
}
std::vector<sk::ObliqueStripStation> OneStation() {
  return {{0.0, 1.0, sk::PanelSymmetricSection({{0.0, -0.1}, {0.1, -0.1}, {0.1, 0.0}}, 8)}};
}
bool Names(const std::string& error, const std::string& word) { return error.find(word) != std::string::npos; }
}  // namespace

TEST_CASE("oblique strip options and mass name the field they refuse") {
  std::string e;
  sk::ObliqueStripOptions o;
  CHECK(o.IsValid(&e));
  o.speed_m_s = std::numeric_limits<double>::quiet_NaN();
  CHECK_FALSE(o.IsValid(&e));
  CHECK(Names(e, "speed_m_s"));
  o.speed_m_s = -2.0;  // any finite speed (negative: astern)
  CHECK(o.IsValid(&e));
  o = {};
  o.rho_kg_m3 = 0.0;
  CHECK_FALSE(o.IsValid(&e));
  CHECK(Names(e, "rho_kg_m3"));
  o = {};
  o.section.gauss_points = 1;
  CHECK_FALSE(o.IsValid(&e));
  CHECK(Names(e, "section: gauss_points"));

  sk::ObliqueMassProperties m = Mass();
  CHECK(m.IsValid(&e));
  m.mass_kg = -1.0;
  CHECK_FALSE(m.IsValid(&e));
  CHECK(Names(e, "mass_kg"));
  m = Mass();
  m.inertia_kg_m2(0, 2) = 0.1;  // not mirrored in (2, 0)
  CHECK_FALSE(m.IsValid(&e));
  CHECK(Names(e, "symmetric"));
  m = Mass();
  m.z_g_m = std::numeric_limits<double>::quiet_NaN();
  CHECK_FALSE(m.IsValid(&e));
  CHECK(Names(e, "z_g_m"));
}

TEST_CASE("oblique strip theory refuses impossible requests") {
  const sk::ObliqueStripOptions o;
  CHECK_THROWS_AS(sk::SolveObliqueStripTheory(OneStation(), Mass(), {}, {90.0}, o), std::invalid_argument);
  CHECK_THROWS_AS(sk::SolveObliqueStripTheory(OneStation(), Mass(), {0.0}, {90.0}, o), std::invalid_argument);
  CHECK_THROWS_AS(sk::SolveObliqueStripTheory(OneStation(), Mass(), {1.0}, {std::nan("")}, o),
                  std::invalid_argument);
  CHECK_THROWS_AS(sk::SolveObliqueStripTheory({{0.0, 1.0, {}}}, Mass(), {1.0}, {90.0}, o), std::invalid_argument);
  sk::ObliqueStripOptions moving;
  moving.speed_m_s = 2.0;  // following seas at ω 6: ω_e = ω − ω²U/g < 0
  CHECK_THROWS_AS(sk::SolveObliqueStripTheory(OneStation(), Mass(), {6.0}, {0.0}, moving), std::domain_error);
  // A valid request with no headings still gives the radiation coefficients.
  const auto r = sk::SolveObliqueStripTheory(OneStation(), Mass(), {1.0, 2.0}, {}, o);
  CHECK(r.frequencies.size() == 2);
  CHECK(r.waves.empty());
  CHECK(r.frequencies[0].added_mass(2, 2) > 0.0);
}
