// Forward speed in the oblique-sea strip theory (seakeeping/motions/oblique_strip_theory.h, the
// Salvesen–Tuck–Faltinsen speed terms):
//  - at U = 0 the results are bit for bit those of the zero-speed path as it was before the speed terms were
//    added;
//  - in head seas (β = 180°) heave and pitch equal the head-sea STF method (strip_theory_stf.h) on the same
//    hull, stations and speed: the same sectional potentials, the same x-derivative on the station grid and
//    the same transom term, two independent assemblies;
//  - a port–starboard symmetric hull in head and following seas at speed has no sway, roll or yaw;
//  - the speed terms keep the Timman–Newman symmetry A_jk(U) = A_kj(−U), B_jk(U) = B_kj(−U) on a hull without
//    a transom (the Wigley hull), and the transom terms break it (as in STF 1970);
//  - the closed forms of the speed terms (STF 1970) on a prism with a transom: B33 = ∫b33 + U a33(x_A), ...
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/motions/oblique_strip_theory.h"
#include "seakeeping/motions/strip_theory_stf.h"
#include "seakeeping/strip/strip_geometry.h"
#include "support/delft372_hull.h"
#include "support/wigley_hull.h"
#include "support/wigley_oblique.h"

using namespace hullopt;
using C = std::complex<double>;

namespace {
constexpr double kRho = 1000.0, kG = 9.81;

sk::ObliqueStripOptions Options(double speed) {
  sk::ObliqueStripOptions o;
  o.rho_kg_m3 = kRho;
  o.g_m_s2 = kG;
  o.speed_m_s = speed;
  return o;
}

// One demihull of Delft 372 on the centreline: a slender monohull with a transom, L 3 m, T 0.15 m.
hull::HullForm Delft372Demihull() {
  hull::HullForm h = hullopt::testing::Delft372Hull(HULLOPT_SOURCE_DIR);
  h.type = "monohull";
  h.bodies[0].y_centre_m = 0.0;
  return h;
}
}  // namespace

TEST_CASE("oblique strip theory at U = 0: bit for bit the zero-speed path") {
  // A regression anchor, not a physics reference (the zero-speed physics is checked against the 3D data in
  // verification_oblique_strip_capytaine): the values the zero-speed path gave before the speed terms were
  // added (main at 165fee0, this build's compiler and flags), printed with %a. The check is bit identity, so
  // the reference is necessarily that code's output; a different compiler or libm may need them re-taken from
  // that commit.
  const std::vector<std::array<C, 5>> rao = {
      {{{-0x1.01804a0258324p-55, -0x1.102ce85224fc9p-53},
        {0x1.aa74a2f58269dp-1, -0x1.5738e895f5e8fp-7},
        {-0x1.2c039c1972347p-50, -0x1.ea79ed79ef806p-59},
        {-0x1.e5c4dbe98423cp-7, -0x1.d3554843443fap-1},
        {0x1.f6c6df98c044ep-55, 0x1.5177844ee57fp-55}}},
      {{{-0x1.214e862a86fbdp-57, -0x1.3c550999f21a7p-60},
        {-0x1.9666dad588c09p-4, 0x1.3a8c0c135c136p-4},
        {0x1.996c531e4d0dp-59, 0x1.1e8ad0aac8d8ep-54},
        {0x1.e779d0610f2b7p-6, -0x1.9b76df159109p-6},
        {-0x1.15d09eecae0b8p-57, -0x1.fbc01db54ae67p-58}}},
      {{{-0x1.bd3784882be48p-11, -0x1.7e78a9c579da9p-1},
        {0x1.ecee4ed6f1acp-1, -0x1.bcd888f530e9ep-9},
        {-0x1.337d7c255c7d9p-6, -0x1.9ccb4fcde7448p+0},
        {-0x1.fa69612ad3961p-9, -0x1.028d3c47904b6p-1},
        {0x1.7465e415b0bbap-2, -0x1.d3adc1bacaac3p-11}}},
      {{{0x1.35621e3c2570ep-4, -0x1.a9f3ada062879p-6},
        {0x1.019258fa72247p-1, 0x1.969b89ab98e71p-7},
        {0x1.a433ca6570134p-2, 0x1.62e54427b00b6p+0},
        {-0x1.2d7fa641a77ep-4, -0x1.ab40a4237dc49p-2},
        {0x1.071d3d72e7e33p-3, 0x1.3ff6c2e3ccefp-10}}},
  };
  const std::vector<std::array<double, 10>> diag = {
      // A22, B22, A33, B33, ... A66, B66 per ω
      {{0x1.5a26b75ed279dp+7, 0x1.5c1ac959ecf11p+5, 0x1.08c437c51b782p+6, 0x1.182e55f255f8dp+8,
        0x1.a0be14b6b98eep-3, 0x1.216b79bcce047p-5, 0x1.5cde0c60dc61ep+4, 0x1.7869a66e3226fp+6,
        0x1.08b82e025436ap+7, 0x1.adc12c47e42b4p+4}},
      {{0x1.0caaab0298236p+7, 0x1.7ff0e36409e33p+9, 0x1.efef2afaeb406p+4, 0x1.12e7ad392624bp+8,
        0x1.682793cf402e3p-3, 0x1.29cc39606dbfbp-1, 0x1.2d1a235a840c7p+3, 0x1.77607f4986bcfp+6,
        0x1.bfd57e707cc1ap+6, 0x1.38026f32f875ep+9}},
  };
  const auto r =
      sk::SolveObliqueStripTheory(test::WigleyObliqueStations(12, 12), test::WigleyObliqueMass(0.13),
                                  {3.0, 6.0}, {180.0, 120.0}, Options(0.0));
  for (std::size_t h = 0; h < 2; ++h)
    for (std::size_t f = 0; f < 2; ++f)
      for (int d = 1; d < 6; ++d) {
        INFO("heading " << h << " frequency " << f << " dof " << d + 1);
        CHECK(r.Wave(h, f).rao[d] == rao[h * 2 + f][d - 1]);
      }
  for (std::size_t f = 0; f < 2; ++f)
    for (int d = 1; d < 6; ++d) {
      CHECK(r.frequencies[f].added_mass(d, d) == diag[f][2 * (d - 1)]);
      CHECK(r.frequencies[f].damping(d, d) == diag[f][2 * (d - 1) + 1]);
      CHECK(r.Wave(1, f).omega_e_rad_s == r.Wave(1, f).omega_rad_s);
    }
}

namespace {
// The oblique path at β = 180° against the head-sea STF method with the same Cs damping on both sides (the
// head-sea model's sectional damping ½ Cs ρ U B (v − ζ_t), head_sea_ship_model.h; the oblique path's
// ObliqueStripOptions::damping_cs, its own assembly of the same term).
void CompareWithHeadSeaStf(double cs) {
  sk::StripGeometryOptions geo;
  geo.sections = 20;
  geo.panels = 12;
  const double U = 0.5 * std::sqrt(kG * 3.0);  // Fn 0.5
  const auto g = sk::StripKernelGeometry(Delft372Demihull(), geo, U, kRho, kG);
  sk::MotionOptions mo;
  mo.damping_cs = cs;
  const hull::MassProperties mp{43.535, 1.41, 0.782, 0.34};
  const sk::HeadSeaShipModel model(g, mp, mo);
  const std::vector<double> omegas{2.0, 3.0, 4.0, 5.0, 6.0, 8.0};
  const auto rows = sk::FrequencyDomainSectionRows(g, geo.panels);
  const auto stf = sk::StripTheoryCoefficients(model, omegas, rows);
  const auto stf_rao = sk::SolveStripTheoryRaos(model, omegas, rows);

  // The same stations; the CG height at the centre of buoyancy, so that the oblique C55 = ρg(I_L + V(z_B −
  // z_G)) is the head-sea method's hydrostatic strip sum ρg Σ B x² w (which has no V·BG term), and without
  // the longitudinal Froude–Krylov moment (the head-sea method's Froude–Krylov uses the strip normals only).
  std::vector<sk::ObliqueStripStation> st;
  for (int n = 0; n < g.Steps(); ++n) st.push_back({g.x_m[n], g.Weight(n), g.panels[n]});
  sk::ObliqueMassProperties m;
  m.mass_kg = mp.mass_kg;
  m.x_g_m = mp.lcg_m_from_ap;
  m.z_g_m = sk::ObliqueStationHydrostatics(st, m.x_g_m).z_b_m;
  m.inertia_kg_m2.diagonal() << mp.mass_kg * 0.01, mp.mass_kg * mp.kyy_m * mp.kyy_m, mp.mass_kg * 0.5;
  auto o = Options(U);
  o.longitudinal_froude_krylov = false;
  o.damping_cs = cs;
  const auto r = sk::SolveObliqueStripTheory(st, m, omegas, {180.0}, o);
  double depth = 0.0;  // the largest vertical extent of a panel
  for (const auto& s : st)
    for (const auto& p : s.panels) depth = std::max(depth, std::fabs(p.z2 - p.z1));

  // By construction the two differ in two quadratures only, both of the incident wave and the potential:
  //  - the head-sea rows integrate ψ n_z at panel midpoints (one point), the 2D solver's a33, b33 with its
  //    own rule: 1e-6 relative (verification_strip_theory_sections, "R·n_z = −(iω a33 + b33)");
  //  - the diffraction's e^{kz} over a panel: the head-sea method at the panel midpoint, the oblique one
  //    by Gauss–Legendre, a relative difference (k h)²/24 per panel, h a panel's vertical extent.
  // Radiation coefficients therefore to 1e-5 of the matrix scale (measured: 1e-15, the rows and the 2D
  // solver's a, b agree to rounding on these sections), the diffraction to 1.5 (k h)²/24 of itself with the
  // largest h (the total heave excitation differs by 2.6e-3 at ω 8), the RAOs to the same.
  constexpr double kRows = 1e-5;
  for (std::size_t f = 0; f < omegas.size(); ++f) {
    const auto& w = r.Wave(0, f);
    const auto& c = stf[f];
    INFO("omega " << omegas[f]);
    CHECK(w.omega_e_rad_s == Approx(c.omega_e_rad_s).epsilon(1e-14));
    const int idx[2] = {2, 4};
    const double a_scale = std::max(std::fabs(c.A(0, 0)), std::fabs(c.A(1, 1)));
    const double b_scale = std::max(std::fabs(c.B(0, 0)), std::fabs(c.B(1, 1)));
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        const double l = i + j == 1 ? 3.0 : 1.0;  // a length to compare A35 with A33, A55 (L ≈ 3 m)
        // c.A and c.B are the strip force's in-phase and quadrature parts, so c.A also holds the Cs term's
        // U x5 part, which the oblique result keeps as a restoring term: A − C_cs/ω_e².
        const double a_cs = w.cs_restoring(idx[i], idx[j]) / (w.omega_e_rad_s * w.omega_e_rad_s);
        CHECK(std::fabs(w.added_mass(idx[i], idx[j]) - a_cs - c.A(i, j)) < kRows * a_scale * l);
        // c.B includes the Cs damping, the oblique result keeps it apart.
        CHECK(std::fabs(w.damping(idx[i], idx[j]) + w.cs_damping(idx[i], idx[j]) - c.B(i, j)) <
              kRows * b_scale * l);
      }
    const double k = omegas[f] * omegas[f] / kG;
    const double tol_wave = std::max(1e-5, 1.5 * k * depth * k * depth / 24.0);
    CHECK(std::abs(w.froude_krylov[2] - c.froude_krylov[0]) < 1e-9 * std::abs(c.froude_krylov[0]));
    CHECK(std::abs(w.diffraction[2] - c.diffraction[0]) < tol_wave * std::abs(c.diffraction[0]));
    CHECK(std::abs(w.diffraction[4] - c.diffraction[1]) < tol_wave * std::abs(c.diffraction[1]));
    CHECK(std::abs(w.excitation[2] - c.Exciting(0)) < tol_wave * std::abs(c.Exciting(0)));
    CHECK(std::abs(w.excitation[4] - c.Exciting(1)) < tol_wave * std::abs(c.Exciting(1)));
    CHECK(std::abs(w.rao[2] - stf_rao.heave[f]) < tol_wave * std::abs(stf_rao.heave[f]));
    CHECK(std::abs(w.rao[4] - stf_rao.pitch[f]) < tol_wave * std::abs(stf_rao.pitch[f]));
    std::printf("omega %.1f heave %.6f %.6f pitch %.6f %.6f  dA33 %.2e dB35 %.2e dF3 %.2e\n", omegas[f],
                std::abs(w.rao[2]), std::abs(stf_rao.heave[f]), std::abs(w.rao[4]),
                std::abs(stf_rao.pitch[f]), std::fabs(w.added_mass(2, 2) - c.A(0, 0)) / a_scale,
                std::fabs(w.damping(2, 4) + w.cs_damping(2, 4) - c.B(0, 1)) / b_scale,
                std::abs(w.excitation[2] - c.Exciting(0)) / std::abs(c.Exciting(0)));
  }
}
}  // namespace

TEST_CASE("oblique strip theory in head seas at speed: heave and pitch of the head-sea STF method") {
  CompareWithHeadSeaStf(0.0);
}

TEST_CASE("oblique strip theory in head seas at speed with Cs damping: the head-sea STF method's") {
  // Cs 0.1, near the top of the paper's range (0–0.15), so that the term moves the heave peak.
  CompareWithHeadSeaStf(0.1);
}

TEST_CASE(
    "oblique strip theory at speed: a symmetric hull in head and following seas has no sway, roll or yaw") {
  const double U = 0.3 * std::sqrt(kG * test::kWigleyL);  // Fn 0.3
  // Following seas need ω_e = ω − kU > 0: ω < g/U = 6.0 rad/s.
  const std::vector<double> omegas{2.0, 3.5, 5.0};
  const auto r = sk::SolveObliqueStripTheory(test::WigleyObliqueStations(20, 16),
                                             test::WigleyObliqueMass(0.13), omegas, {180.0, 0.0}, Options(U));
  // As at zero speed (verification_oblique_strip_symmetry): the zeros come from exactly cancelling mirror
  // pairs, so they are rounding-level relative to the heave and pitch values.
  constexpr double kRounding = 1e-9;
  for (std::size_t h = 0; h < 2; ++h)
    for (std::size_t f = 0; f < omegas.size(); ++f) {
      const auto& w = r.Wave(h, f);
      CHECK(test::AntisymmetricFraction(w) < kRounding);
      CHECK(std::abs(w.rao[4]) > 1e-3 * (std::abs(w.rao[2]) + std::abs(w.rao[4])));  // pitch is excited
      const double a = w.added_mass.cwiseAbs().maxCoeff(), b = w.damping.cwiseAbs().maxCoeff();
      for (int d : {1, 3, 5})
        for (int e : {2, 4}) {
          CHECK(std::fabs(w.added_mass(d, e)) < kRounding * a);
          CHECK(std::fabs(w.damping(d, e)) < kRounding * b);
        }
    }
}

TEST_CASE("oblique strip theory speed terms: Timman–Newman A_jk(U) = A_kj(−U) without a transom") {
  // Beam seas (ω_e = ω at ±U, so both speeds share the sections). The Wigley stations on the cell faces have
  // uniform spacing equal to their weights and the end stations are dry (the hull ends in points, so no
  // transom or entry term; on the cell midpoints the end stations are wet and their end terms break the
  // symmetry by 20–100 % of the largest entry): the discrete speed
  // terms are then Σ w Z (a_j + (U/iω_e) a_j')(iω_e a_k − U a_k'), symmetric under j↔k, U→−U when Z is, and Z
  // is symmetric to the 2D solver's reciprocity (1e-3 of the largest entry on 16 panels,
  // verification_oblique_strip_symmetry).
  constexpr double kReciprocity = 1e-3;
  const double U = 0.3 * std::sqrt(kG * test::kWigleyL);
  sk::StripGeometryOptions geo;
  geo.sections = 20;
  geo.panels = 16;
  geo.layout = sk::StationLayout::kCellFaces;
  const auto st = sk::ObliqueStripStations(
      test::WigleyHull(test::kWigleyL, test::kWigleyB, test::kWigleyT, 201, 61), geo);
  REQUIRE(st.front().panels.empty());
  REQUIRE(st.back().panels.empty());
  const auto mass = test::WigleyObliqueMass(0.13);
  for (double w : {3.0, 6.0}) {
    const auto plus = sk::SolveObliqueStripTheory(st, mass, {w}, {90.0}, Options(U)).Wave(0, 0);
    const auto minus = sk::SolveObliqueStripTheory(st, mass, {w}, {90.0}, Options(-U)).Wave(0, 0);
    const double a = plus.added_mass.cwiseAbs().maxCoeff(), b = plus.damping.cwiseAbs().maxCoeff();
    INFO("omega " << w);
    CHECK((plus.added_mass - minus.added_mass.transpose()).cwiseAbs().maxCoeff() < kReciprocity * a);
    CHECK((plus.damping - minus.damping.transpose()).cwiseAbs().maxCoeff() < kReciprocity * b);
    // The speed terms are there: A35 and A53 differ by 2(U/ω²)B33⁰ (STF 1970), well above the tolerance.
    CHECK(std::fabs(plus.added_mass(2, 4) - plus.added_mass(4, 2)) > 20 * kReciprocity * a);
  }
}

TEST_CASE("oblique strip theory speed terms: STF's closed forms on a prism with a transom") {
  // A prism of uniform section (weights equal to the spacing), stations on the cell midpoints from x = 0 to
  // L, the transom at the aftmost station x_A: the grid's backward difference telescopes, and the hull sums
  // are STF 1970's with their transom terms, evaluated here from the entry's zero-speed sectional a, b:
  //   A33 = ∫a33 − (U/ω²) b33(x_A),  B33 = ∫b33 + U a33(x_A),
  //   A35 = −∫ξa33 − (U/ω²)B33⁰ + (U/ω²) ξ_A b33(x_A) − (U²/ω²) a33(x_A),
  //   B35 = −∫ξb33 + U A33⁰ − U ξ_A a33(x_A) − (U²/ω²) b33(x_A),
  //   A53 = −∫ξa33 + (U/ω²)B33⁰ + (U/ω²) ξ_A b33(x_A),   B53 = −∫ξb33 − U A33⁰ − U ξ_A a33(x_A),
  //   A55 = ∫ξ²a33 + (U²/ω²)A33⁰ − (U/ω²) ξ_A² b33(x_A) + (U²/ω²) ξ_A a33(x_A),
  //   B55 = ∫ξ²b33 + (U²/ω²)B33⁰ + U ξ_A² a33(x_A) + (U²/ω²) ξ_A b33(x_A),
  // and for sway and yaw the same with a22, b22 and the signs of STF's yaw (n_6 = ξ n_2):
  //   A26 = ∫ξa22 + (U/ω²)B22⁰ − (U/ω²) ξ_A b22(x_A) + (U²/ω²) a22(x_A),
  //   B26 = ∫ξb22 − U A22⁰ + U ξ_A a22(x_A) + (U²/ω²) b22(x_A),
  //   A62 = ∫ξa22 − (U/ω²)B22⁰ − (U/ω²) ξ_A b22(x_A),   B62 = ∫ξb22 + U A22⁰ + U ξ_A a22(x_A),
  //   A44 = ∫a44 − (U/ω²) b44(x_A),  B44 = ∫b44 + U a44(x_A).
  // On the station grid (strip_theory_stf.h's backward difference) the integrals of the a_j' (speed) terms
  // are sums over the stations forward of the aftmost one, Σ_{n≠A} Δx, and the others Σ w: the forms above
  // with those sums, checked below to rounding; as Δx → 0 both are STF's integrals.
  const int n_st = 16;
  const double length = 4.0, dx = length / n_st, U = 2.0, w = 4.0;
  std::vector<std::array<double, 2>> half;
  for (int i = 0; i <= 50; ++i) half.push_back({0.2, -0.25 * (1.0 - i / 50.0)});
  half.front() = {0.0, -0.25};
  std::vector<sk::ObliqueStripStation> st;
  for (int n = 0; n < n_st; ++n) st.push_back({(n + 0.5) * dx, dx, sk::PanelSymmetricSection(half, 16)});
  sk::ObliqueMassProperties m;
  m.mass_kg = kRho * 0.4 * 0.25 * length;
  m.x_g_m = 0.5 * length;
  m.z_g_m = -0.1;
  m.inertia_kg_m2.diagonal() << m.mass_kg * 0.02, m.mass_kg * 1.5, m.mass_kg * 1.5;
  const auto r = sk::SolveObliqueStripTheory(st, m, {w}, {90.0}, Options(U));
  const auto& wr = r.Wave(0, 0);
  const auto& sec = r.frequencies[wr.frequency_entry].sections[0];  // every section alike
  // The discrete sums: ∫f ≈ Σ w f(ξ_n), and the grid's derivative term Σ a_j(ξ_n)(G_n − G_{n−1}) =
  // a_j(ξ_A) G_A − Σ_{n<N−1} (a_j(ξ_{n+1}) − a_j(ξ_n)) G_n: for a linear a_j, a_j' Σ_{n<N−1} Δx G_n.
  double s0 = 0, s1 = 0, s2 = 0, t0 = 0, t1 = 0;  // Σ w, Σ wξ, Σ wξ²; Σ_{n<N−1} Δx, Σ_{n<N−1} Δx ξ
  for (int n = 0; n < n_st; ++n) {
    const double xi = st[n].x_m - m.x_g_m;
    s0 += dx;
    s1 += dx * xi;
    s2 += dx * xi * xi;
    if (n > 0) {  // every station but the aftmost (x ascending here, so n = 0 is the aftmost)
      t0 += dx;
      t1 += dx * xi;
    }
  }
  const double xa = st[0].x_m - m.x_g_m;
  // Expected F_jk = ω² A − iω B from the operator form with these sums (j, k over heave/pitch).
  const C iw(0.0, w);
  const C z33 = -(iw * sec.added_mass(1, 1) + sec.damping(1, 1));
  const C s = U / iw;
  // G_k(ξ) = z c_k(ξ): heave c = iω, pitch c = −iωξ + U.
  const C f33 = z33 * iw * s0 + s * z33 * iw;
  const C f35 = z33 * (-iw * s1 + U * s0) + s * z33 * (-iw * xa + U);
  // pitch row: a_5 = −ξ, a_5' = −1: Σ w(−ξ)G + s[(−ξ_A) G_A − (−1) Σ_{n<N−1} Δx G_n]... with a_j' Σ Δx G_n:
  const C f53 = -z33 * iw * s1 + s * (-xa * z33 * iw + (-1.0) * z33 * iw * t0);
  const C f55 =
      z33 * (iw * s2 - U * s1) + s * (-xa * z33 * (-iw * xa + U) + (-1.0) * z33 * (-iw * t1 + U * t0));
  // The same sums in another order: rounding, 1e-12 of the largest term (the hull length squared times F33).
  const double tol = 1e-12 * std::abs(f33) * length * length;
  auto check = [&](C f, int j, int k) {
    const C got(w * w * wr.added_mass(j, k), -w * wr.damping(j, k));
    INFO("F" << j + 1 << k + 1 << " expected " << f << " got " << got);
    CHECK(std::abs(got - f) < tol);
  };
  check(f33, 2, 2);
  check(f35, 2, 4);
  check(f53, 4, 2);
  check(f55, 4, 4);
  // Sway and yaw: a_2 = 1, c_2 = iω; a_6 = ξ, a_6' = 1, c_6 = iωξ − U.
  const C z22 = -(iw * sec.added_mass(0, 0) + sec.damping(0, 0));
  const C f22 = z22 * iw * s0 + s * z22 * iw;
  const C f26 = z22 * (iw * s1 - U * s0) + s * z22 * (iw * xa - U);
  const C f62 = z22 * iw * s1 + s * (xa * z22 * iw + z22 * iw * t0);
  const C f66 = z22 * (iw * s2 - U * s1) + s * (xa * z22 * (iw * xa - U) + z22 * (iw * t1 - U * t0));
  check(f22, 1, 1);
  check(f26, 1, 5);
  check(f62, 5, 1);
  check(f66, 5, 5);
  // And STF's continuous forms: the transom term U a33(x_A) in B33 exactly (the heave row has a_3' = 0).
  CHECK(wr.damping(2, 2) == Approx(s0 * sec.damping(1, 1) + U * sec.added_mass(1, 1)).epsilon(1e-12));
  CHECK(wr.added_mass(2, 2) ==
        Approx(s0 * sec.added_mass(1, 1) - U / (w * w) * sec.damping(1, 1)).epsilon(1e-12));
  CHECK(wr.damping(3, 3) == Approx(s0 * sec.damping(2, 2) + U * sec.added_mass(2, 2)).epsilon(1e-12));
}

TEST_CASE("oblique strip theory at speed refuses an encounter frequency <= 0") {
  const double U = 3.0;  // following seas: ω_e = ω − ω²U/g <= 0 from ω = g/U = 3.27 rad/s
  CHECK_THROWS_AS(sk::SolveObliqueStripTheory(test::WigleyObliqueStations(8, 8),
                                              test::WigleyObliqueMass(0.13), {4.0}, {0.0}, Options(U)),
                  std::domain_error);
  CHECK_NOTHROW(sk::SolveObliqueStripTheory(test::WigleyObliqueStations(8, 8), test::WigleyObliqueMass(0.13),
                                            {4.0}, {90.0}, Options(U)));
}

TEST_CASE("oblique strip theory Cs damping on a box in beam seas: the waterline closed forms") {
  // A box barge, L 10 m, B 2 m, T 0.5 m, 21 stations on cell faces (trapezoid weights: constants integrate
  // exactly), at 2 m/s in beam seas (β = 90°, ω_e = ω). The Cs term's heave damping is ½ Cs ρ U ∫B dx = ½ Cs ρ
  // U B L and its wave part iω ½ Cs ρ U L ∫_{−B/2}^{B/2} e^{−iky} dy = iω ½ Cs ρ U L B sin(kB/2)/(kB/2)
  // (the wave varies across the waterline; along the hull it has one phase in beam seas). Tolerances: 1e-12
  // relative for sums of exact terms; 1e-10 for the Gauss–Legendre waterline integral of a smooth exponential.
  constexpr double L = 10.0, B = 2.0, T = 0.5, U = 2.0, cs = 0.1, w = 2.0;
  constexpr int kStations = 21;
  std::vector<sk::ObliqueStripStation> st;
  for (int n = 0; n < kStations; ++n) {
    const double dx = L / (kStations - 1);
    sk::ObliqueStripStation s;
    s.x_m = n * dx;
    s.weight_m = (n == 0 || n == kStations - 1) ? 0.5 * dx : dx;
    // Port waterline → keel → starboard waterline, several panels on the bottom.
    s.panels.push_back({0.5 * B, 0.0, 0.5 * B, -T});
    for (int j = 0; j < 4; ++j)
      s.panels.push_back({0.5 * B - j * B / 4, -T, 0.5 * B - (j + 1) * B / 4, -T});
    s.panels.push_back({-0.5 * B, -T, -0.5 * B, 0.0});
    st.push_back(s);
  }
  sk::ObliqueMassProperties m;
  m.mass_kg = kRho * L * B * T;
  m.x_g_m = 0.5 * L;
  m.z_g_m = -0.5 * T;
  m.inertia_kg_m2.diagonal() << m.mass_kg * 0.16, m.mass_kg * 8.3, m.mass_kg * 8.3;
  auto o = Options(U);
  o.damping_cs = cs;
  const auto r = sk::SolveObliqueStripTheory(st, m, {w}, {90.0}, o);
  const auto& wr = r.Wave(0, 0);
  const double damp = 0.5 * cs * kRho * U, k = w * w / kG;
  CHECK(wr.cs_damping(2, 2) == Approx(damp * B * L).epsilon(1e-12));
  const C expected = C(0.0, w) * damp * L * B * std::sin(0.5 * k * B) / (0.5 * k * B);
  CHECK(std::abs(wr.cs_excitation[2] - expected) < 1e-10 * std::abs(expected));
  // Sway, roll and yaw carry none of it, and without Cs there is none.
  for (int d : {1, 3, 5}) CHECK(wr.cs_excitation[d] == C(0.0));
  auto o0 = Options(U);
  const auto r0 = sk::SolveObliqueStripTheory(st, m, {w}, {90.0}, o0);
  CHECK(r0.Wave(0, 0).cs_damping.isZero(0.0));
}
