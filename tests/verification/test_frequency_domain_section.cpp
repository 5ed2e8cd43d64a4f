// Frequency-domain 2D panel solver (seakeeping/frequency_domain_section.h) against independent results:
//  - heaving semicircle: Ursell's (1949) multipole solution, a source plus wave-free multipoles
//      (a/r)^{2m} [cos 2mθ + νr/(2m−1) cos(2m−1)θ]  (F. Ursell, "On the heaving motion of a circular cylinder
//      on the surface of a fluid", Q. J. Mech. Appl. Math. 2 (1949) 218–231), solved here by least squares on
//      the exact circle — no panels, no lid, no panel quadrature; it shares only the Green function of a
//      point source, which tests/unit/test_frequency_domain_green.cpp checks against its integral definition;
//  - the infinite-frequency limit a33 → ρπR²/2 of the semicircle (the image of a translating circle);
//  - energy balance: damping against the radiated wave amplitude far away, b33 = ρg²(|A+|² + |A−|²)/(2ω³);
//  - Haskind: exciting force from the diffraction solution against the one from the radiation potential;
//  - irregular frequencies: the lid removes the spurious peak of a rectangle at its first irregular
//  frequency, and changes nothing else (independent of its own panelling; with and without it agree away
//  from the irregular band; lid on converges to Ursell);
//  - panel convergence 14, 28, 56 (printed) and two semicircles side by side (symmetric, finite);
//  - the direct formulation (SectionFormulation::kDirect) against the same references, against the source
//    formulation where both are converged, and on a bulb under a strut, whose re-entrant junction makes the
//    source density singular.
#include <Eigen/Dense>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <cstdio>

#include "seakeeping/green/frequency_domain_green.h"
#include "seakeeping/sections/frequency_domain_section.h"
#include "seakeeping/sections/section_shapes.h"
#include "support/bulb_under_strut.h"
#include "support/ursell_semicircle.h"

using namespace hullopt::sk;
using C = std::complex<double>;

namespace {

constexpr double kRho = 1000.0, kG = 9.81, kR = 1.0;
const double kM0 = kRho * M_PI * kR * kR / 2;  // ρπR²/2 [kg/m]

FrequencyDomainOptions Options() {
  FrequencyDomainOptions o;
  o.rho_kg_m3 = kRho;
  o.g_m_s2 = kG;
  return o;
}

std::vector<Panel> Semicircle(int n) { return PanelSymmetricSection(SemicircleContour(kR, 4000), n); }

struct Coefficients {
  double a, b;  // a33/(ρπR²/2), b33/(ρπR²ω/2)
};

// n body panels; lid panels as FrequencyDomainOptions::lid_panels (−1 automatic, 0 none).
Coefficients Panels(int n, double nuR, int lid = -1, SectionFormulation form = SectionFormulation::kSource) {
  const double w = std::sqrt(nuR * kG / kR);
  FrequencyDomainOptions o = Options();
  o.lid_panels = lid;
  o.formulation = form;
  const auto h = SolveSectionFrequencyDomain({Semicircle(n)}, w, o);
  return {h.a33() / kM0, h.b33() / (kM0 * w)};
}

// Ursell's multipole solution (support/ursell_semicircle.h), in the units of Coefficients.
Coefficients Ursell(double nuR, int multipoles = 14, int collocation = 60) {
  const auto u = hullopt::testing::UrsellSemicircleHeave(nuR, multipoles, collocation);
  return {u.a33, u.b33};
}

}  // namespace

TEST_CASE("Ursell multipole reference is converged in the number of multipoles", "[fd][semicircle]") {
  // Exponential convergence in the multipoles: 10 and 14 terms agree to 1e-4, two orders below the 1% used
  // against the panel solver (this is the reference's own error).
  constexpr double kTolReference = 1e-4;
  for (double nuR : {0.1, 0.5, 1.0, 2.0}) {
    const Coefficients a = Ursell(nuR, 10), b = Ursell(nuR, 14);
    CHECK(std::fabs(a.a - b.a) < kTolReference);
    CHECK(std::fabs(a.b - b.b) < kTolReference);
  }
}

TEST_CASE("heaving semicircle: panel solver converges to Ursell's multipole solution", "[fd][semicircle]") {
  // Constant-strength flat panels with midpoint collocation converge at first order in the panel size here
  // (the missing self-curvature term of each panel; the same O(1/N) is seen in the pure Rankine
  // infinite-frequency problem), so compare the Richardson extrapolation 2·X(112) − X(56) within 1% of the
  // curve's scale, and the 56-panel result within 3.5%.
  constexpr double kTolExtrapolated = 0.01;
  constexpr double kTol56 = 0.035;
  std::printf(
      "semicircle heave: nuR, a33/(rho pi R^2/2) and b33/(rho pi R^2 omega/2): Ursell | 14 28 56 panels\n");
  for (double nuR : {0.1, 0.25, 0.5, 1.0, 1.5, 2.0}) {
    const Coefficients u = Ursell(nuR);
    const Coefficients p14 = Panels(14, nuR), p28 = Panels(28, nuR), p56 = Panels(56, nuR),
                       p112 = Panels(112, nuR);
    std::printf("  %4.2f  a %.4f | %.4f %.4f %.4f (112: %.4f)   b %.4f | %.4f %.4f %.4f (112: %.4f)\n", nuR,
                u.a, p14.a, p28.a, p56.a, p112.a, u.b, p14.b, p28.b, p56.b, p112.b);
    INFO("nuR = " << nuR);
    // Scale: the larger of the local value and the damping curve's peak order (≈ 1 for both).
    CHECK(std::fabs(2 * p112.a - p56.a - u.a) <= kTolExtrapolated * std::max(1.0, u.a));
    CHECK(std::fabs(2 * p112.b - p56.b - u.b) <= kTolExtrapolated * std::max(1.0, u.b));
    CHECK(std::fabs(p56.a - u.a) <= kTol56 * std::max(1.0, u.a));
    CHECK(std::fabs(p56.b - u.b) <= kTol56 * std::max(1.0, u.b));
  }
}

TEST_CASE("semicircle high-frequency added mass tends to rho pi R^2 / 2", "[fd][semicircle]") {
  // At νR = 200 the finite-frequency correction is O(1/(νR)) ≈ 0.5%; with 112 panels the O(1/N) panel error
  // is ≈ 0.6% (Rankine check), so the required 1% is met without extrapolation at 112 panels.
  constexpr double kTolHighFrequency = 0.01;
  const Coefficients p = Panels(112, 200.0);
  std::printf("semicircle nuR = 200, 112 panels: a33/(rho pi R^2/2) = %.4f\n", p.a);
  CHECK(std::fabs(p.a - 1.0) <= kTolHighFrequency);
}

TEST_CASE("energy balance and Haskind relation hold", "[fd][semicircle]") {
  // Far-field amplitude and pressure integral come from the same sources by different operations; their
  // mismatch is a discretisation error that halves with the panel size (≈ 1% at 56 panels), so 2%.
  constexpr double kTolEnergy = 0.02;
  // Exciting force from the diffraction problem against the Haskind form (radiation potential only): two
  // different boundary-value problems; 2% of the Froude–Krylov scale ρgB.
  constexpr double kTolHaskind = 0.02;
  const auto panels = Semicircle(56);
  for (double nuR : {0.2, 0.7, 1.3, 2.5}) {
    const double w = std::sqrt(nuR * kG / kR);
    const auto h = SolveSectionFrequencyDomain({panels}, w, Options());
    const double b_far =
        kRho * kG * kG * (std::norm(h.far_wave_plus[1]) + std::norm(h.far_wave_minus[1])) / (2 * w * w * w);
    INFO("nuR = " << nuR << " b33 " << h.b33() << " from far field " << b_far);
    CHECK(std::fabs(b_far / h.b33() - 1) <= kTolEnergy);
    // Symmetric body: heave radiates equal waves both ways.
    CHECK(std::abs(h.far_wave_plus[1]) == Approx(std::abs(h.far_wave_minus[1])).epsilon(1e-9));
    const double scale = kRho * kG * 2 * kR;
    CHECK(std::abs(h.exciting_force[1] - h.exciting_force_haskind[1]) <= kTolHaskind * scale);
    // 2D Haskind–damping relation for a symmetric body: |F3/A| = sqrt(ρ g² b33 / ω), with F3 from
    // diffraction.
    const double f_from_damping = std::sqrt(kRho * kG * kG * h.b33() / w);
    CHECK(std::fabs(std::abs(h.exciting_force[1]) / f_from_damping - 1) <= kTolEnergy);
  }
}

TEST_CASE("long waves: heave exciting force tends to the hydrostatic rho g B", "[fd][semicircle]") {
  // At νR = 0.002 the diffraction part is O(ν ln ν) and FK is ρgB(1 − O(νR)): 1% is ample.
  constexpr double kTolLongWave = 0.01;
  const double w = std::sqrt(0.002 * kG / kR);
  const auto h = SolveSectionFrequencyDomain({Semicircle(28)}, w, Options());
  CHECK(std::abs(h.exciting_force[1]) == Approx(kRho * kG * 2 * kR).epsilon(kTolLongWave));
}

TEST_CASE("the lid removes the irregular frequency of a rectangle", "[fd][irregular]") {
  // Rectangle B = 2 m, T = 1 m: the interior Dirichlet eigenproblem has its first symmetric mode
  // cos(πy/B) sinh(k(z+T)), k = π/B, at ν = k coth(kT), i.e. νB/2 = (π/2) coth(π/2) = 1.7126.
  const double B = 2.0, T = 1.0;
  const double k = M_PI / B;
  const double nu_irr = k / std::tanh(k * T);
  const auto panels = PanelSymmetricSection(RectangleContour(B, T), 40);
  auto run = [&](double nu, int lid) {
    FrequencyDomainOptions o = Options();
    o.lid_panels = lid;
    return SolveSectionFrequencyDomain({panels}, std::sqrt(nu * kG), o);
  };
  // With the lid: the value at the irregular frequency lies on the smooth curve through its neighbours (±3%);
  // without: it does not. Smoothness measure: deviation from the mean of the two neighbours, relative.
  const double d = 0.03 * nu_irr;
  auto kink = [&](int lid) {
    const double b0 = run(nu_irr, lid).b33(), bm = run(nu_irr - d, lid).b33(),
                 bp = run(nu_irr + d, lid).b33();
    return std::fabs(b0 - 0.5 * (bm + bp)) / std::fabs(b0);
  };
  const double with_lid = kink(-1), without_lid = kink(0);
  std::printf(
      "rectangle B/T = 2 at its first irregular frequency nuB/2 = %.4f: b33 kink with lid %.2e, without "
      "%.2e\n",
      nu_irr * B / 2, with_lid, without_lid);
  // A smooth curve has a second difference of O(d²)·(curvature) ≈ 6e-3 relative here (measured with the lid);
  // the unremoved irregular frequency gives O(1).
  constexpr double kTolSmooth = 1e-2;
  CHECK(with_lid < kTolSmooth);
  CHECK(without_lid > 10 * kTolSmooth);
}

TEST_CASE("the lid does not change the exterior solution away from irregular frequencies",
          "[fd][irregular]") {
  // The exterior problem is unique, so in the continuous problem the lid sources change nothing outside the
  // body at any frequency; only discretisation error may differ. Three checks on the heaving semicircle:
  //  (a) refining the lid alone (14 body panels, 4 … 56 lid panels) must leave the result where it is: the
  //      lid's own discretisation error is the only thing that changes. 1% of the curve's scale
  //      max(1, Ursell) — a fifth of the 14-panel body error (≈ 5% against Ursell) — so the lid cannot
  //      dominate the error budget. (A lid condition with singular corner densities drifted here by 0.21 ρA,
  //      growing by ≈ 0.06 per lid halving.)
  //  (b) body and lid refined together (automatic lid): the Richardson extrapolation 2·X(28) − X(14) of the
  //      O(1/N) panel error is within 1% of Ursell (the tolerance of the 56/112-panel check above), at all
  //      frequencies including near the semicircle's irregular frequency νR ≈ 1.8.
  //  (c) with and without lid at 56 panels, away from the irregular band (|νR − 1.8| > 0.75): within 1% of
  //      the scale, below the body's own 56-panel error against Ursell (1–2% in a33).
  constexpr double kTolLidRefinement = 0.01;
  constexpr double kTolExtrapolated = 0.01;
  constexpr double kTolLidOnOff = 0.01;
  for (double nuR : {0.25, 1.0}) {
    const Coefficients u = Ursell(nuR);
    double a_lo = 1e9, a_hi = -1e9, b_lo = 1e9, b_hi = -1e9;
    std::printf("semicircle nuR %.2f, 14 body panels, lid 4 7 14 28 56:", nuR);
    for (int lid : {4, 7, 14, 28, 56}) {
      const Coefficients p = Panels(14, nuR, lid);
      std::printf("  a %.4f b %.4f", p.a, p.b);
      a_lo = std::min(a_lo, p.a), a_hi = std::max(a_hi, p.a);
      b_lo = std::min(b_lo, p.b), b_hi = std::max(b_hi, p.b);
    }
    std::printf("  (Ursell a %.4f b %.4f)\n", u.a, u.b);
    INFO("nuR = " << nuR);
    CHECK(a_hi - a_lo <= kTolLidRefinement * std::max(1.0, u.a));
    CHECK(b_hi - b_lo <= kTolLidRefinement * std::max(1.0, u.b));
  }
  for (double nuR : {0.1, 0.25, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0}) {
    const Coefficients u = Ursell(nuR);
    const Coefficients p14 = Panels(14, nuR), p28 = Panels(28, nuR);
    INFO("nuR = " << nuR << ": 14 panels a " << p14.a << " b " << p14.b << ", 28 panels a " << p28.a << " b "
                  << p28.b << ", Ursell a " << u.a << " b " << u.b);
    CHECK(std::fabs(2 * p28.a - p14.a - u.a) <= kTolExtrapolated * std::max(1.0, u.a));
    CHECK(std::fabs(2 * p28.b - p14.b - u.b) <= kTolExtrapolated * std::max(1.0, u.b));
  }
  for (double nuR : {0.1, 0.25, 0.5, 1.0, 3.0}) {
    const Coefficients u = Ursell(nuR);
    const Coefficients on = Panels(56, nuR, -1), off = Panels(56, nuR, 0);
    INFO("nuR = " << nuR << ": 56 panels lid on a " << on.a << " b " << on.b << ", off a " << off.a << " b "
                  << off.b);
    CHECK(std::fabs(on.a - off.a) <= kTolLidOnOff * std::max(1.0, u.a));
    CHECK(std::fabs(on.b - off.b) <= kTolLidOnOff * std::max(1.0, u.b));
  }
}

TEST_CASE("two semicircles side by side: symmetric, finite, different from twice one", "[fd][multihull]") {
  const double spacing = 3.0 * kR;
  const auto port = PanelSymmetricSection(SemicircleContour(kR, 4000), 28, +spacing / 2);
  const auto stbd = PanelSymmetricSection(SemicircleContour(kR, 4000), 28, -spacing / 2);
  const double w = std::sqrt(1.0 * kG / kR);
  const auto two = SolveSectionFrequencyDomain({port, stbd}, w, Options());
  const auto one = SolveSectionFrequencyDomain({Semicircle(28)}, w, Options());
  CHECK(std::isfinite(two.a33()));
  CHECK(two.b33() > 0);
  CHECK(std::abs(two.far_wave_plus[1]) == Approx(std::abs(two.far_wave_minus[1])).epsilon(1e-9));
  // Interaction at 3R spacing changes the pair's coefficients by more than 5% from twice a single hull.
  CHECK(std::fabs(two.a33() / (2 * one.a33()) - 1) + std::fabs(two.b33() / (2 * one.b33()) - 1) > 0.05);
  // Energy balance holds for the pair as well, with the single body's 2% at its 56 panels per body (the
  // mismatch is the O(1/N) panel error: 1.97% at 28 panels, too close to the limit to be a robust check).
  constexpr double kTolEnergy = 0.02;
  auto energy_mismatch = [&](const SectionHydrodynamics& h) {
    const double b_far =
        kRho * kG * kG * (std::norm(h.far_wave_plus[1]) + std::norm(h.far_wave_minus[1])) / (2 * w * w * w);
    return std::fabs(b_far / h.b33() - 1);
  };
  const auto port56 = PanelSymmetricSection(SemicircleContour(kR, 4000), 56, +spacing / 2);
  const auto stbd56 = PanelSymmetricSection(SemicircleContour(kR, 4000), 56, -spacing / 2);
  const auto two56 = SolveSectionFrequencyDomain({port56, stbd56}, w, Options());
  std::printf("two semicircles at 3R, nuR = 1: energy mismatch %.4f (28 panels each), %.4f (56)\n",
              energy_mismatch(two), energy_mismatch(two56));
  CHECK(energy_mismatch(two56) <= kTolEnergy);
}

TEST_CASE("heave solver (Rankine parts once, half strip when symmetric) equals the full solver", "[fd][heave]") {
  // SectionHeaveSolver solves the same discrete problem as SolveSectionFrequencyDomain, for a mirror-
  // symmetric strip on one half (σ of mirror panels equal): the heave potentials agree to rounding amplified
  // by the system's condition (~1e-13 here); 1e-11 of the largest potential leaves room for that and is far
  // below any error of the reduction itself (a wrong mirror pairing is O(1)).
  constexpr double kTolRounding = 1e-11;
  const auto port = PanelSymmetricSection(SemicircleContour(kR, 4000), 28, +1.5 * kR);
  const auto stbd = PanelSymmetricSection(SemicircleContour(kR, 4000), 28, -1.5 * kR);
  const auto box = PanelSymmetricSection(RectangleContour(1.6 * kR, 0.7 * kR), 20, -1.5 * kR);
  FrequencyDomainOptions odd_lid = Options();
  odd_lid.lid_panels = 7;  // a lid panel on the axis, its own mirror image
  struct Case {
    const char* name;
    std::vector<std::vector<Panel>> sections;
    FrequencyDomainOptions options;
    bool symmetric;
  };
  const Case cases[] = {
      {"semicircle", {Semicircle(28)}, Options(), true},
      {"semicircle, odd lid", {Semicircle(28)}, odd_lid, true},
      {"two semicircles", {port, stbd}, Options(), true},
      {"semicircle and rectangle (not symmetric)", {port, box}, Options(), false},
  };
  for (const auto& c : cases) {
    INFO(c.name);
    const SectionHeaveSolver solver(c.sections, c.options);
    CHECK(solver.mirror_symmetric() == c.symmetric);
    for (double nuR : {0.1, 0.8, 2.5}) {
      INFO("nu R = " << nuR);
      const double w = std::sqrt(nuR * kG / kR);
      const Eigen::VectorXcd full = SolveSectionFrequencyDomain(c.sections, w, c.options).radiation_potential.col(1);
      const Eigen::VectorXcd psi = solver.HeavePotential(w);
      REQUIRE(psi.size() == full.size());
      CHECK((psi - full).cwiseAbs().maxCoeff() <= kTolRounding * full.cwiseAbs().maxCoeff());
    }
  }
}

TEST_CASE("options are validated", "[fd]") {
  FrequencyDomainOptions o;
  std::string e;
  CHECK(o.IsValid(&e));
  o.rho_kg_m3 = -1;
  CHECK_FALSE(o.IsValid(&e));
  CHECK(e.find("rho_kg_m3") != std::string::npos);
  CHECK_THROWS_AS(SolveSectionFrequencyDomain({Semicircle(14)}, 1.0, o), std::invalid_argument);
  CHECK_THROWS_AS(SolveSectionFrequencyDomain({Semicircle(14)}, -1.0, FrequencyDomainOptions{}),
                  std::invalid_argument);
  CHECK_THROWS_AS(SolveSectionFrequencyDomain({}, 1.0, FrequencyDomainOptions{}), std::invalid_argument);
}

namespace {

constexpr SectionFormulation kDirect = SectionFormulation::kDirect;


}  // namespace

TEST_CASE("direct formulation: heaving semicircle against Ursell at 14 and 28 panels", "[fd][direct]") {
  // Green's identity for the potential needs no curvature term and converges at second order. Measured at 14
  // panels: a33 within 0.5% of Ursell for νR 0.1–3, b33 within 1.3% up to νR = 1 and +2.9%, +3.5% at 2, 3
  // (the radiated wave is generated within 1/ν of the waterline, which 7 panels a side resolve with two or
  // three). Tolerances: a33 1% at 14 panels; b33 2% at 14 panels up to νR = 1 (the accuracy the strip methods
  // ask of a section), 4% above; 28 panels 1.5% for both everywhere (second order: a quarter of 14's error).
  constexpr double kTolA14 = 0.01, kTolB14 = 0.02, kTolB14High = 0.04, kTol28 = 0.015;
  std::printf("direct formulation, semicircle: nuR, a33 and b33 (as above): Ursell | 14 28 panels\n");
  for (double nuR : {0.1, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0}) {
    const Coefficients u = Ursell(nuR);
    const Coefficients p14 = Panels(14, nuR, -1, kDirect), p28 = Panels(28, nuR, -1, kDirect);
    std::printf("  %4.2f  a %.4f | %.4f %.4f   b %.4f | %.4f %.4f\n", nuR, u.a, p14.a, p28.a, u.b, p14.b, p28.b);
    INFO("nuR = " << nuR);
    CHECK(std::fabs(p14.a / u.a - 1) <= kTolA14);
    CHECK(std::fabs(p14.b / u.b - 1) <= (nuR <= 1.0 ? kTolB14 : kTolB14High));
    CHECK(std::fabs(p28.a / u.a - 1) <= kTol28);
    CHECK(std::fabs(p28.b / u.b - 1) <= kTol28);
  }
}

TEST_CASE("direct formulation: energy balance, Haskind, and the source formulation's limit", "[fd][direct]") {
  // The same checks as for the source formulation, with its tolerances: far field against pressure integral
  // 2%, diffraction against Haskind 2% of ρgB. Both formulations discretise the same exterior problem, so at
  // 112 panels they agree within their panel errors (under 0.5% each against Ursell there): 1%.
  constexpr double kTolEnergy = 0.02, kTolHaskind = 0.02, kTolFormulations = 0.01;
  FrequencyDomainOptions o = Options();
  o.formulation = kDirect;
  const auto panels = Semicircle(56);
  for (double nuR : {0.2, 0.7, 1.3, 2.5}) {
    const double w = std::sqrt(nuR * kG / kR);
    const auto h = SolveSectionFrequencyDomain({panels}, w, o);
    const double b_far =
        kRho * kG * kG * (std::norm(h.far_wave_plus[1]) + std::norm(h.far_wave_minus[1])) / (2 * w * w * w);
    INFO("nuR = " << nuR << " b33 " << h.b33() << " from far field " << b_far);
    CHECK(std::fabs(b_far / h.b33() - 1) <= kTolEnergy);
    CHECK(std::abs(h.far_wave_plus[1]) == Approx(std::abs(h.far_wave_minus[1])).epsilon(1e-9));
    CHECK(std::abs(h.exciting_force[1] - h.exciting_force_haskind[1]) <= kTolHaskind * kRho * kG * 2 * kR);
  }
  for (double nuR : {0.25, 1.0, 2.0}) {
    const Coefficients d = Panels(112, nuR, -1, kDirect), s = Panels(112, nuR);
    INFO("nuR = " << nuR << ": direct a " << d.a << " b " << d.b << ", source a " << s.a << " b " << s.b);
    CHECK(std::fabs(d.a - s.a) <= kTolFormulations * std::max(1.0, s.a));
    CHECK(std::fabs(d.b - s.b) <= kTolFormulations * std::max(1.0, s.b));
  }
}

TEST_CASE("direct formulation: the lid points remove the irregular frequency of a rectangle", "[fd][direct]") {
  // As for the source formulation (the same rectangle, frequency and smoothness measure): the extended
  // condition at the lid points must leave the b33 curve smooth through the first irregular frequency,
  // without them it must not be.
  const double B = 2.0, T = 1.0, k = M_PI / B, nu_irr = k / std::tanh(k * T), d = 0.03 * nu_irr;
  const auto panels = PanelSymmetricSection(RectangleContour(B, T), 40);
  auto b33 = [&](double nu, int lid) {
    FrequencyDomainOptions o = Options();
    o.lid_panels = lid;
    o.formulation = kDirect;
    return SolveSectionFrequencyDomain({panels}, std::sqrt(nu * kG), o).b33();
  };
  auto kink = [&](int lid) {
    const double b0 = b33(nu_irr, lid);
    return std::fabs(b0 - 0.5 * (b33(nu_irr - d, lid) + b33(nu_irr + d, lid))) / std::fabs(b0);
  };
  const double with_lid = kink(-1), without_lid = kink(0);
  std::printf("direct formulation, rectangle at nuB/2 = %.4f: b33 kink with lid points %.2e, without %.2e\n",
              nu_irr * B / 2, with_lid, without_lid);
  constexpr double kTolSmooth = 1e-2;
  CHECK(with_lid < kTolSmooth);
  CHECK(without_lid > 10 * kTolSmooth);
}

TEST_CASE("re-entrant corner: a bulb under a strut at 14 panels", "[fd][direct]") {
  // Bulb R = 1 m, centre 1.8 m deep, strut half-width 0.25 m, νR = 0.08 (a SWATH bulb at 0.9 rad/s): the
  // two formulations converge to the same a33 (224 panels: within 0.5%, their difference at 112 being
  // under 1%), the source formulation from 11% low at 14 panels (first order: the source density is
  // singular like r^−0.3 at the junction), the direct one from 2.3% low. Tolerances: the two limits 1%; the
  // direct formulation at 14 panels within 3% of the converged value (the resolution the study asks of a
  // hull, 40 × 14 against 80 × 28); the source formulation at 14 panels more than 6% off (the reason the
  // direct formulation is offered; if it ever is not, this check says the source formulation improved).
  constexpr double kTolLimits = 0.01, kTolDirect14 = 0.03, kSourceMiss14 = 0.06;
  const double w = std::sqrt(0.08 * kG / kR);
  auto a33 = [&](int n, SectionFormulation f) {
    FrequencyDomainOptions o = Options();
    o.formulation = f;
    return SolveSectionFrequencyDomain({PanelSymmetricSection(hullopt::testing::BulbUnderStrut(1.0, 1.8, 0.25), n)}, w, o).a33();
  };
  const double s14 = a33(14, SectionFormulation::kSource), s224 = a33(224, SectionFormulation::kSource);
  const double d14 = a33(14, kDirect), d28 = a33(28, kDirect), d224 = a33(224, kDirect);
  std::printf("bulb under a strut, a33 [kg/m]: source 14 %.1f, 224 %.1f; direct 14 %.1f, 28 %.1f, 224 %.1f\n", s14,
              s224, d14, d28, d224);
  CHECK(std::fabs(d224 / s224 - 1) <= kTolLimits);
  CHECK(std::fabs(d14 / d224 - 1) <= kTolDirect14);
  CHECK(std::fabs(s14 / s224 - 1) > kSourceMiss14);
}

TEST_CASE("direct formulation: the heave solver gives the full solver's potential", "[fd][direct][heave]") {
  FrequencyDomainOptions o = Options();
  o.formulation = kDirect;
  const auto panels = Semicircle(14);
  const SectionHeaveSolver solver({panels}, o);
  const double w = std::sqrt(1.0 * kG / kR);
  const Eigen::VectorXcd full = SolveSectionFrequencyDomain({panels}, w, o).radiation_potential.col(1);
  CHECK((solver.HeavePotential(w) - full).cwiseAbs().maxCoeff() <= 1e-12 * full.cwiseAbs().maxCoeff());
}
