// Zero-speed oblique-sea strip theory (seakeeping/motions/oblique_strip_theory.h) against its own symmetries
// and against the 2D section solver it is built on:
//  - a hull symmetric port–starboard and fore–aft in head (180°) and following (0°) seas: no sway, roll or
//    yaw excitation or motion, and symmetric radiation matrices with no sway–heave coupling;
//  - a long prism in beam seas: heave and roll excitation are the 2D section's own beam-sea exciting force
//    (the direct diffraction solution, not the Haskind form the strip sum uses) times the length;
//  - the 2D energy (Haskind) relation, which the strip formulation satisfies exactly per section:
//    b_jj = ω/(2ρg²) (|f_j(90°)|² + |f_j(270°)|²); on the prism the hull sums keep it;
//  - Newman's 3D relation B_jj = kω/(4πρg²) ∫|F_j(β)|² dβ, which strip theory satisfies only approximately
//    (printed, with the tolerance the slender-body approximation allows);
//  - long waves (ω = 0.5 rad/s, kL = 0.08) on the Wigley hull: the hull follows the wave (heave 1, sway
//    |sin β| 90° behind the crest, pitch |cos β|, or without the longitudinal Froude–Krylov moment the strip
//    limit, see below), and the beam-sea roll RAO the 3D data quote at 0.5–1.5 rad/s;
//  - hydrostatics of the panelled Wigley hull against its closed forms.
#include <catch2/catch.hpp>
#include <cmath>
#include <array>
#include <complex>
#include <cstdio>
#include <vector>

#include "seakeeping/green/panel.h"
#include "seakeeping/motions/oblique_strip_theory.h"
#include "seakeeping/sections/frequency_domain_section.h"
#include "support/wigley_oblique.h"

using namespace hullopt;

namespace {
constexpr double kRho = 1000.0, kG = 9.81;

sk::ObliqueStripOptions Options() {
  sk::ObliqueStripOptions o;
  o.rho_kg_m3 = kRho;
  o.g_m_s2 = kG;
  return o;
}

// A prism of the Wigley midship section y = (B/2)(1 − (z/T)²) (smooth but for the keel), beam 0.3 m, draught
// 0.1875 m, length 20 m in 20 stations, 40 panels per section.
constexpr double kPrismB = 0.3, kPrismT = 0.1875, kPrismL = 20.0;
std::vector<sk::Panel> PrismSection() {
  std::vector<std::array<double, 2>> half;
  for (int i = 0; i <= 200; ++i) {
    const double z = -kPrismT * (1.0 - i / 200.0);
    half.push_back({0.5 * kPrismB * (1.0 - z * z / (kPrismT * kPrismT)), z});
  }
  return sk::PanelSymmetricSection(half, 40);
}
std::vector<sk::ObliqueStripStation> Prism() {
  std::vector<sk::ObliqueStripStation> out;
  for (int n = 0; n < 20; ++n) out.push_back({(n + 0.5) * kPrismL / 20, kPrismL / 20, PrismSection()});
  return out;
}
sk::ObliqueMassProperties PrismMass() {
  sk::ObliqueMassProperties m;
  m.mass_kg = kRho * kPrismB * kPrismT * kPrismL;
  m.x_g_m = 0.5 * kPrismL;
  m.z_g_m = -0.05;
  m.inertia_kg_m2.diagonal() << m.mass_kg * 0.02, m.mass_kg * 30.0, m.mass_kg * 30.0;
  return m;
}
}  // namespace

TEST_CASE("oblique strip theory: head and following seas on a symmetric hull excite no sway, roll or yaw") {
  const std::vector<double> omegas{2.0, 4.0, 6.0, 8.0};
  const auto r = sk::SolveObliqueStripTheory(test::WigleyObliqueStations(20, 16), test::WigleyObliqueMass(0.13),
                                             omegas, {180.0, 0.0}, Options());
  // Rounding: the zeros come from ∫ e^{kz} n_y ds over a mirror-symmetric section (exactly cancelling pairs)
  // and from the symmetric Haskind integrals, so they are rounding-level relative to the heave values.
  constexpr double kRounding = 1e-9;
  for (std::size_t h = 0; h < 2; ++h)
    for (std::size_t f = 0; f < omegas.size(); ++f) {
      const auto& w = r.Wave(h, f);
      CHECK(test::AntisymmetricFraction(w) < kRounding);
      CHECK(std::abs(w.excitation[4]) > 1e-3 * std::abs(w.excitation[2]));  // pitch is excited
    }
  for (const auto& fr : r.frequencies) {
    const double a = fr.added_mass.cwiseAbs().maxCoeff(), b = fr.damping.cwiseAbs().maxCoeff();
    // The 2D solver's matrices are symmetric to its discretisation (reciprocity, 1e-3 of the largest entry on
    // 16 panels); T a Tᵀ and the strip sums keep that.
    constexpr double kReciprocity = 1e-3;
    CHECK((fr.added_mass - fr.added_mass.transpose()).cwiseAbs().maxCoeff() < kReciprocity * a);
    CHECK((fr.damping - fr.damping.transpose()).cwiseAbs().maxCoeff() < kReciprocity * b);
    for (int d : {1, 3, 5})  // sway, roll, yaw do not couple with heave and pitch
      for (int e : {2, 4}) {
        CHECK(std::fabs(fr.added_mass(d, e)) < kRounding * a);
        CHECK(std::fabs(fr.damping(d, e)) < kRounding * b);
      }
  }
}

TEST_CASE("oblique strip theory: a long prism in beam seas has the 2D section's exciting force times its length") {
  const std::vector<double> omegas{2.0, 4.0, 6.0, 9.0};
  const auto m = PrismMass();
  const auto r = sk::SolveObliqueStripTheory(Prism(), m, omegas, {90.0, 270.0}, Options());
  sk::FrequencyDomainOptions so;
  so.rho_kg_m3 = kRho;
  so.g_m_s2 = kG;
  for (std::size_t f = 0; f < omegas.size(); ++f) {
    const auto h2d = sk::SolveSectionFrequencyDomain({PrismSection()}, omegas[f], so);
    const auto& w = r.Wave(0, f);
    // The strip sum uses the Haskind form; the 2D reference solves the diffraction problem itself: two
    // boundary-value problems that agree to the panel discretisation (2 %, as the 2D solver's own
    // Haskind-vs-direct check on the semicircle in test_frequency_domain_section).
    constexpr double kDirectVsHaskind = 0.02;
    const std::complex<double> f3 = h2d.exciting_force[1] * kPrismL;
    const std::complex<double> f4 = (h2d.exciting_force[2] + m.z_g_m * h2d.exciting_force[0]) * kPrismL;
    const std::complex<double> f2 = h2d.exciting_force[0] * kPrismL;
    CHECK(std::abs(w.excitation[2] - f3) < kDirectVsHaskind * std::abs(f3));
    CHECK(std::abs(w.excitation[1] - f2) < kDirectVsHaskind * std::abs(f2));
    std::printf("omega %.1f direct vs strip: F2 %.4g %.4g F3 %.4g %.4g F4 %.4g %.4g\n", omegas[f],
                std::abs(f2), std::abs(w.excitation[1]), std::abs(f3), std::abs(w.excitation[2]), std::abs(f4),
                std::abs(w.excitation[3]));
    CHECK(std::abs(w.excitation[3] - f4) < kDirectVsHaskind * (std::abs(f4) + 0.2 * kPrismB * std::abs(f2)));
    // 2D energy relation on the hull sums (every section alike): B_jj L = ω/(2ρg²)(|F_j(90°)|² + |F_j(270°)|²).
    // Exact for the strip formulation up to the panel discretisation (damping from the pressure integral,
    // excitation from FK + Haskind): 2 %, the 2D solver's own energy-balance tolerance on 56 panels.
    constexpr double kEnergy = 0.02;
    for (int d : {1, 2, 3}) {
      const double rhs = omegas[f] / (2 * kRho * kG * kG) *
                         (std::norm(r.Wave(0, f).excitation[d]) + std::norm(r.Wave(1, f).excitation[d]));
      INFO("dof " << d + 1 << " omega " << omegas[f]);
      std::printf("energy dof %d omega %.1f: B L %.5g, from |F|^2 %.5g\n", d + 1, omegas[f],
                  r.frequencies[f].damping(d, d) * kPrismL, rhs);
      CHECK(r.frequencies[f].damping(d, d) * kPrismL == Approx(rhs).epsilon(kEnergy));
    }
  }
}

TEST_CASE("oblique strip theory: Newman's relation on the Wigley hull holds only approximately") {
  const std::vector<double> omegas{3.0, 5.0, 7.0};
  std::vector<double> headings;
  for (int i = 0; i < 36; ++i) headings.push_back(10.0 * i);
  const auto r = sk::SolveObliqueStripTheory(test::WigleyObliqueStations(30, 16), test::WigleyObliqueMass(0.13),
                                             omegas, headings, Options());
  for (std::size_t f = 0; f < omegas.size(); ++f) {
    const double k = r.frequencies[f].k_per_m, w = omegas[f];
    for (int d : {1, 2, 3, 4, 5}) {
      double sum = 0.0;
      for (std::size_t h = 0; h < headings.size(); ++h) sum += std::norm(r.Wave(h, f).excitation[d]);
      const double newman = k * w / (4 * M_PI * kRho * kG * kG) * sum * (2 * M_PI / headings.size());
      const double b = r.frequencies[f].damping(d, d);
      std::printf("Newman: omega %.1f dof %d  B %.5g  from |F|^2 %.5g  ratio %.3f\n", w, d + 1, b, newman,
                  newman / b);
      // Heave radiates mostly broadside from a slender hull, where the strip sections' 2D waves are right:
      // within 10 % at ω >= 3 rad/s (0.96–1.08 measured). Sway, roll, pitch and yaw are printed only: their
      // 3D radiation towards the ends is what strip theory lacks (ratios 0.09–1.4).
      constexpr double kNewmanHeave = 0.1;
      if (d == 2) CHECK(std::fabs(newman / b - 1) < kNewmanHeave);
    }
  }
}

TEST_CASE("oblique strip theory: hydrostatics of the panelled Wigley hull") {
  const auto st = test::WigleyObliqueStations(40, 20);
  const double L = test::kWigleyL, B = test::kWigleyB, T = test::kWigleyT;
  const auto h = sk::ObliqueStationHydrostatics(st, 0.5 * L);
  // Midpoint rule over 40 stations on polynomials of x (O(Δx²), about 1e-3 relative for the cubic b³) and
  // 20 chords per section (the inscribed polygon loses the segments between chords and contour, O(1/N²),
  // 0.3 % of the volume).
  constexpr double kQuadrature = 5e-3;
  std::printf("hydrostatics: V %.6g (exact %.6g), A_wp %.6g (%.6g), z_B %.6g (%.6g), I_T %.6g (%.6g), I_L %.6g "
              "(%.6g)\n", h.volume_m3, 4 * L * B * T / 9, h.waterplane_area_m2, 2 * L * B / 3, h.z_b_m, -3 * T / 8,
              h.waterplane_i_t_m4, 4 * L * B * B * B / 105, h.waterplane_i_l_cg_m4, B * L * L * L / 30);
  CHECK(h.volume_m3 == Approx(4 * L * B * T / 9).epsilon(kQuadrature));
  CHECK(h.waterplane_area_m2 == Approx(2 * L * B / 3).epsilon(kQuadrature));
  CHECK(h.z_b_m == Approx(-(T - 5 * T / 8)).epsilon(kQuadrature));
  CHECK(h.waterplane_i_t_m4 == Approx(4 * L * B * B * B / 105).epsilon(kQuadrature));
  CHECK(h.waterplane_i_l_cg_m4 == Approx(B * L * L * L / 30).epsilon(kQuadrature));
  // Fore–aft symmetric hull: the centres at midships, to the rounding of the hull's interpolation and
  // waterline cut at each station (not bit-symmetric fore and aft).
  constexpr double kSymmetric = 1e-6;
  CHECK(std::fabs(h.x_b_m - 0.5 * L) < kSymmetric * L);
  CHECK(std::fabs(h.x_f_m - 0.5 * L) < kSymmetric * L);
}

TEST_CASE("oblique strip theory: long waves on the Wigley hull") {
  const std::vector<double> omegas{0.5, 1.0, 1.5};
  const std::vector<double> headings{90.0, 135.0, 180.0};
  // At 0.5 rad/s the first corrections are O(kT) = 0.005 and O(ω²(m + A)/C): 0.5 % for heave and pitch; sway
  // (no restoring, only the orbital velocity's decay over the draught) 1 %; phases within 1°.
  constexpr double kLongWave = 0.005, kLongWaveSway = 0.01, kPhaseDeg = 1.0;
  for (double kg : {0.13, 0.17})
    for (bool longitudinal : {true, false}) {
      const auto m = test::WigleyObliqueMass(kg);
      sk::ObliqueStripOptions o = Options();
      o.longitudinal_froude_krylov = longitudinal;
      const auto r = sk::SolveObliqueStripTheory(test::WigleyObliqueStations(40, 20), m, omegas, headings, o);
      const auto& hs = r.hydrostatics;
      // The pitch moment of the pressure on the longitudinal slope (n_x) is ρgkV(z_B − z_G) cosβ in long waves;
      // with it the hull follows the wave slope (pitch 1 per kA; Capytaine 1.0006), without it (conventional
      // strip theory) pitch is C55-limited at I_L/(I_L + V(z_B − z_G)) (1.0036 at KG 0.13, 1.0149 at 0.17).
      const double pitch_limit =
          longitudinal ? 1.0
                       : hs.waterplane_i_l_cg_m4 / (hs.waterplane_i_l_cg_m4 + hs.volume_m3 * (hs.z_b_m - m.z_g_m));
      for (std::size_t h = 0; h < headings.size(); ++h) {
        const double beta = headings[h] * M_PI / 180.0;
        const auto& w = r.Wave(h, 0);  // 0.5 rad/s
        INFO("KG " << kg << " heading " << headings[h] << " longitudinal FK " << longitudinal);
        CHECK(std::abs(w.rao[2]) == Approx(1.0).epsilon(kLongWave));
        CHECK(std::fabs(std::arg(w.rao[2])) * 180 / M_PI < kPhaseDeg);
        if (std::fabs(std::sin(beta)) > 0.5) {
          CHECK(std::abs(w.rao[1]) == Approx(std::fabs(std::sin(beta))).epsilon(kLongWaveSway));
          CHECK(std::fabs(std::arg(w.rao[1]) * 180 / M_PI + 90.0) < kPhaseDeg);
        }
        if (std::fabs(std::cos(beta)) > 0.5) {
          CHECK(std::abs(w.rao[4]) == Approx(std::fabs(std::cos(beta)) * pitch_limit).epsilon(kLongWave));
          CHECK(std::fabs(std::arg(w.rao[4]) * 180 / M_PI + 90.0) < kPhaseDeg);
        }
      }
      // Beam-sea roll per kA at 0.5, 1.0, 1.5 rad/s from the 3D data (data/peers-oblique/SOURCE.md, "Long
      // waves"): roll is 2D-exact in long waves; the panelled C44 differs from the closed form by 1.7 % of its
      // (small) value at KG 0.17 and 0.3 % at KG 0.13, which the near-static roll RAO carries: 2 %.
      constexpr double kLongWaveRoll = 0.02;
      const std::vector<double> roll_3d = kg == 0.13 ? std::vector<double>{1.009, 1.046, 1.115}
                                                     : std::vector<double>{0.970, 0.870, 0.737};
      for (std::size_t f = 0; f < omegas.size(); ++f) {
        INFO("KG " << kg << " beam-sea roll at " << omegas[f]);
        CHECK(std::abs(r.Wave(0, f).rao[3]) == Approx(roll_3d[f]).epsilon(kLongWaveRoll));
        CHECK(std::fabs(std::arg(r.Wave(0, f).rao[3]) * 180 / M_PI + 90.0) < kPhaseDeg);
      }
    }
}
