// The time-domain section solver with the current sources' potential from Green's identity
// (BodyPotential::kGreenIdentity) against references independent of it: Ursell's multipole solution for the
// semicircle, and the frequency-domain solver's direct formulation at 224 panels for a bulb under a strut
// (a re-entrant corner, where the source density is singular and the source sum converges at first order).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "seakeeping/sections/frequency_domain_section.h"
#include "seakeeping/sections/section_shapes.h"
#include "seakeeping/strip/strip_operators.h"
#include "seakeeping/strip/td_heave_coefficients.h"
#include "support/bulb_under_strut.h"
#include "support/ursell_semicircle.h"

using namespace hullopt::sk;

namespace {
constexpr double kG = 9.81;
constexpr double kRho = 1025.0;

HeaveCoefficients TimeDomain(const std::vector<Panel>& panels, const std::vector<double>& omega, BodyPotential p) {
  TimeDomainSectionOptions o;
  o.operators.body_potential = p;
  return TimeDomainHeaveCoefficients(panels, omega, kRho, kG, o);
}
}  // namespace

TEST_CASE("Green's-identity body potential: heaving semicircle against Ursell at 14 panels", "[td][verification]") {
  // Measured at 14 panels, νR 0.1–1: a33 within 0.4 % and b33 within 0.3 % of Ursell. Tolerances: the
  // direct formulation's own at 14 panels (verification_frequency_domain_section): a33 1 %, b33 2 % up to
  // νR = 1, the accuracy the strips ask of a section. Above νR ≈ 1.2 the time-domain solution of this
  // semicircle approaches its irregular band near νR 1.8 (the source densities carry the memory in both
  // variants), where Green's identity follows the source densities' error more closely; docs/sections.md.
  constexpr double kTolA = 0.01, kTolB = 0.02;
  const double R = 1.0;
  const auto panels = PanelSymmetricSection(SemicircleContour(R, 4000), 14);
  const std::vector<double> nuR = {0.1, 0.25, 0.5, 1.0};
  std::vector<double> omega;
  for (double k : nuR) omega.push_back(std::sqrt(k * kG / R));
  const auto gi = TimeDomain(panels, omega, BodyPotential::kGreenIdentity);
  const double m0 = kRho * M_PI * R * R / 2;
  std::printf("time domain, Green's identity, semicircle 14 panels: nuR, a33 and b33 / Ursell\n");
  for (std::size_t i = 0; i < nuR.size(); ++i) {
    const auto u = hullopt::testing::UrsellSemicircleHeave(nuR[i]);
    const double a = gi.a33_kg_per_m[i] / m0, b = gi.b33_kg_per_m_s[i] / (m0 * omega[i]);
    std::printf("  %4.2f  a %.4f / %.4f   b %.4f / %.4f\n", nuR[i], a, u.a33, b, u.b33);
    INFO("nuR = " << nuR[i]);
    CHECK(std::fabs(a / u.a33 - 1) <= kTolA);
    CHECK(std::fabs(b / u.b33 - 1) <= kTolB);
  }
}

TEST_CASE("Green's-identity body potential: a bulb under a strut", "[td][verification]") {
  // Bulb R = 1 m, centre 1.8 m deep, strut half-width 0.25 m, νR = 0.08 (a SWATH bulb at 0.9 rad/s).
  // Reference: the frequency-domain direct formulation at 224 panels (a different solver and Green function;
  // within 0.5 % of the source formulation's 224-panel value). Measured, a33 against it at 14 / 28 / 56 / 112
  // panels: Green's identity −5.3 / −2.1 / −0.8 / −0.4 %, source sum −13.1 / −4.6 / −1.7 / −0.8 %. Both
  // converge at about order 1.3, not 2: the memory is carried by the source densities, singular at the
  // junction, in both; Green's identity removes it from the instantaneous part only. Checks: both within
  // 1 % of the reference at 112 panels (the same limit); at 14 panels Green's identity at most half the
  // source sum's error (what the option is for).
  constexpr double kTolLimit = 0.01, kImprovement = 0.5;
  const double w = std::sqrt(0.08 * kG / 1.0);
  const auto contour = hullopt::testing::BulbUnderStrut(1.0, 1.8, 0.25);
  FrequencyDomainOptions fd;
  fd.rho_kg_m3 = kRho;
  fd.g_m_s2 = kG;
  fd.formulation = SectionFormulation::kDirect;
  const double ref = SolveSectionFrequencyDomain({PanelSymmetricSection(contour, 224)}, w, fd).a33();
  auto a33 = [&](int n, BodyPotential p) {
    return TimeDomain(PanelSymmetricSection(contour, n), {w}, p).a33_kg_per_m[0] / ref - 1;
  };
  const double gi14 = a33(14, BodyPotential::kGreenIdentity), src14 = a33(14, BodyPotential::kSourceSum);
  const double gi112 = a33(112, BodyPotential::kGreenIdentity), src112 = a33(112, BodyPotential::kSourceSum);
  std::printf("bulb under a strut, a33 against the reference %.1f kg/m: Green's identity %+.2f %% (14), %+.2f %% "
              "(112); source sum %+.2f %% (14), %+.2f %% (112)\n",
              ref, 100 * gi14, 100 * gi112, 100 * src14, 100 * src112);
  CHECK(std::fabs(gi112) <= kTolLimit);
  CHECK(std::fabs(src112) <= kTolLimit);
  CHECK(std::fabs(gi14) <= kImprovement * std::fabs(src14));
}

TEST_CASE("Green's-identity body potential needs the momentum form", "[td]") {
  StripOperatorOptions o;
  o.body_potential = BodyPotential::kGreenIdentity;
  std::string err;
  CHECK(o.IsValid(&err));
  o.sectional_force = SectionalForce::kPressure;
  CHECK_FALSE(o.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("momentum form"));
}
