// Viscous roll damping (seakeeping/motions/roll_damping.h) against hand computations from the published
// formulae, and in the oblique-sea strip theory:
//  - Kato's skin friction, computed by the code from C_f = 1.328 (3.22 r_f² φa²/(T ν))^(−1/2), against
//    Himeno's (1981) closed form B_F0 = 0.787 ρ S_f r_f² √(ων) evaluated by hand for a stated ship, and
//    Ikeda's speed factor 1 + 4.1 U/(ωL);
//  - the eddy-making coefficient C_R and the bilge-keel component at Kawahara et al.'s example ship (L/B 6,
//    B/d 4, Cb 0.65, Cm 0.98, OG/d −0.2, φa 10°, ω̂ 0.6, bilge keels b/B 0.025, l/L 0.2), evaluated by hand from
//    the published formulae (a separate transcription, not this code), and Ikeda's eddy speed reduction;
//  - the equivalent linearisation B_eq = B1 + (8/(3π)) ω φa B2 against the energy one cycle dissipates;
//  - a round-bilged ship-like hull in beam seas: the roll peak with the damping on is finite and smaller
//    (sanity, not validation).
// Not here: a zero-speed total against a published worked example (Himeno 1981's example or ITTC
// 7.5-02-07-04.5's): neither example's numbers were available to check against.
#include <catch2/catch.hpp>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "seakeeping/green/panel.h"
#include "seakeeping/motions/oblique_strip_theory.h"
#include "seakeeping/motions/roll_damping.h"

using namespace hullopt;

namespace {

sk::RollDampingOptions Ikeda(double phi_deg) {
  sk::RollDampingOptions o;
  o.model = sk::RollDampingModel::kIkeda;
  o.roll_amplitude_rad = phi_deg * M_PI / 180.0;
  o.kinematic_viscosity_m2_s = 1.19e-6;
  o.rho_kg_m3 = 1025.0;
  o.g_m_s2 = 9.81;
  return o;
}

// A stated ship: L 100 m, B 16 m, d 5 m, Cb 0.65, Cm 0.98, CG 1 m above the waterline (OG = −1 m).
sk::RollDampingHull Ship() {
  sk::RollDampingHull h;
  h.length_m = 100.0;
  h.breadth_m = 16.0;
  h.draught_m = 5.0;
  h.block_coefficient = 0.65;
  h.midship_coefficient = 0.98;
  h.og_m = -1.0;
  return h;
}

// Kawahara et al.'s example ship at L = 300 m: B 50 m, d 12.5 m, OG = −2.5 m.
sk::RollDampingHull KawaharaShip(bool bilge_keels) {
  sk::RollDampingHull h;
  h.length_m = 300.0;
  h.breadth_m = 50.0;
  h.draught_m = 12.5;
  h.block_coefficient = 0.65;
  h.midship_coefficient = 0.98;
  h.og_m = -2.5;
  if (bilge_keels) {
    h.bilge_keel_length_m = 0.2 * 300.0;
    h.bilge_keel_breadth_m = 0.025 * 50.0;
  }
  return h;
}

}  // namespace

TEST_CASE("roll damping: Kato's skin friction is Himeno's closed form, with Ikeda's speed factor") {
  const sk::RollDampingHull h = Ship();
  const sk::RollDampingOptions o = Ikeda(5.0);
  const double w = 0.5;
  // By hand: r_f = d [(0.887 + 0.145·0.65)(1.7 + 0.65·3.2) + 2·0.2]/π = 5 (0.98125·3.78 + 0.4)/π = 6.539876 m,
  // S_f = 100 (1.75·5 + 0.65·16) = 1915 m², B_F0 = 0.787 ρ S_f r_f² √(ων) = 0.787·1025·1915·42.77 ·
  // √(0.5·1.19e-6) = 50964 N m s (Himeno 1981; at the Kawahara et al. r_f and S_f).
  const double by_hand = 0.787 * 1025.0 * 1915.0 * 6.539876 * 6.539876 * std::sqrt(0.5 * 1.19e-6);
  CHECK(by_hand == Approx(50964.15).epsilon(1e-6));
  // Himeno prints the constant (4/(3π))·1.328·√(2π/3.22) = 0.78733 to three digits: 4e-4 apart.
  constexpr double kPrintedDigits = 1e-3;
  CHECK(sk::KatoFrictionRollDamping(h, w, o) == Approx(by_hand).epsilon(kPrintedDigits));
  // Laminar Kato: B_F0 does not depend on the roll amplitude (C_f ∝ 1/φa).
  CHECK(sk::KatoFrictionRollDamping(h, w, Ikeda(10.0)) == Approx(sk::KatoFrictionRollDamping(h, w, o)).epsilon(1e-12));
  // Speed factor at U = 10 m/s: 1 + 4.1·10/(0.5·100) = 1.82.
  const auto c = sk::ViscousRollDamping(h, w, 10.0, o);
  CHECK(c.friction == Approx(1.82 * sk::KatoFrictionRollDamping(h, w, o)).epsilon(1e-12));
  CHECK(sk::ViscousRollDamping(h, w, -10.0, o).friction == Approx(c.friction).epsilon(1e-12));
}

TEST_CASE("roll damping: eddy and bilge keels at Kawahara et al.'s example ship, by hand") {
  const sk::RollDampingOptions o = Ikeda(10.0);
  const sk::RollDampingHull h = KawaharaShip(true);
  // ω̂ = ω √(B/(2g)) = 0.6.
  const double w = 0.6 / std::sqrt(50.0 / (2.0 * 9.81));
  // By hand from the published fit (B/d 4, Cb 0.65, Cm 0.98, OG/d −0.2): A_E = f_E1 + f_E2 = 0.0018196 +
  // 0.0184985, B_E1 = −0.1014, B_E2 = 4.2604, B_E3 = 4.0250, C_R = A_E exp(B_E1 + B_E2 Cm^B_E3) = 0.931348.
  constexpr double kCrByHand = 0.9313483;
  // The hand values carry 7 digits.
  constexpr double kHandDigits = 1e-6;
  CHECK(sk::KawaharaEddyCoefficient(h) == Approx(kCrByHand).epsilon(kHandDigits));
  // B̂_E = 4 ω̂ φa C_R/(3π Cb (B/d)³) = 4·0.6·0.174533·0.931348/(3π·0.65·64) = 9.95030e-4, and B̂ = B/(ρ∇B²)
  // √(B/(2g)) with ∇ = L B d Cb.
  const double volume = 300.0 * 50.0 * 12.5 * 0.65;
  const double to_dimensional = 1025.0 * volume * 50.0 * 50.0 * std::sqrt(2.0 * 9.81 / 50.0);
  const auto c = sk::ViscousRollDamping(h, w, 0.0, o);
  const double eddy_eq = sk::EquivalentLinearRollDamping(0.0, c.eddy_quadratic, w, o.roll_amplitude_rad);
  CHECK(eddy_eq / to_dimensional == Approx(9.950302e-4).epsilon(kHandDigits));
  // B̂_BK = A_BK exp(B_BK1 + B_BK2 Cm^B_BK3) ω̂ = 5.652703e-3 (by hand, φa in degrees in the fit).
  const double bk_eq = sk::EquivalentLinearRollDamping(0.0, c.bilge_keel_quadratic, w, o.roll_amplitude_rad);
  CHECK(bk_eq / to_dimensional == Approx(5.652703e-3).epsilon(kHandDigits));
  CHECK(c.lift == 0.0);  // no lift at zero speed
  // Without bilge keels, no bilge-keel damping.
  CHECK(sk::ViscousRollDamping(KawaharaShip(false), w, 0.0, o).bilge_keel_quadratic == 0.0);
  // Ikeda's speed reduction (0.04K)²/(1 + (0.04K)²), K = ωL/U: at K = 25 it halves the eddy damping.
  const double u = w * 300.0 / 25.0;
  CHECK(sk::ViscousRollDamping(h, w, u, o).eddy_quadratic == Approx(0.5 * c.eddy_quadratic).epsilon(1e-12));
  // Hull lift at speed (Ikeda): ½ ρ U L d k_N l_0 l_R (1 − 1.4 OG/l_R + 0.7 OG²/(l_0 l_R)), κ = 0.3 (Cm 0.98):
  // k_N = 2π 12.5/300 + 0.3 (4.1/6 − 0.045) = 0.4532994, l_0 = 3.75, l_R = 6.25, bracket 1 + 0.56 + 0.186667.
  const double lift_by_hand = 0.5 * 1025.0 * u * 300.0 * 12.5 * 0.4532994 * 3.75 * 6.25 * 1.746667;
  CHECK(sk::ViscousRollDamping(h, w, u, o).lift == Approx(lift_by_hand).epsilon(kHandDigits));
}

TEST_CASE("roll damping: B_eq = B1 + 8/(3 pi) omega phi_a B2 dissipates the energy of one cycle") {
  // φ = φa sin ωt; the moment b1 φ̇ + b2 φ̇|φ̇| does work W = ∫ (b1 φ̇ + b2 φ̇|φ̇|) φ̇ dt over a period, and a
  // linear B_eq does B_eq π ω φa². The integral by the midpoint rule on 20000 steps.
  const double b1 = 3.0e4, b2 = 7.0e5, w = 0.7, phi_a = 0.12;
  const int n = 20000;
  const double period = 2.0 * M_PI / w, dt = period / n;
  double work = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = phi_a * w * std::cos(w * (i + 0.5) * dt);
    work += (b1 * v + b2 * v * std::fabs(v)) * v * dt;
  }
  const double b_eq_energy = work / (M_PI * w * phi_a * phi_a);
  // The midpoint rule on a periodic integrand with a kink in |v| at the zeros: error ~ (1/n)², 1e-8 here.
  constexpr double kQuadrature = 1e-7;
  CHECK(sk::EquivalentLinearRollDamping(b1, b2, w, phi_a) == Approx(b_eq_energy).epsilon(kQuadrature));
}

namespace {

// A round-bilged ship-like hull: sections of a box with bilge radius r (B 0.5 m, d 0.15 m, r 0.05 m) whose
// half-breadths are scaled by 1 − s⁴ (s from −1 at the stern to 1 at the bow) along L = 3 m, 24 stations.
constexpr double kL = 3.0, kB = 0.5, kD = 0.15, kR = 0.05;
constexpr int kStations = 24;
std::vector<sk::ObliqueStripStation> RoundBilgeHull() {
  std::vector<sk::ObliqueStripStation> out;
  for (int n = 0; n < kStations; ++n) {
    const double x = (n + 0.5) * kL / kStations, s = 2.0 * x / kL - 1.0, f = 1.0 - s * s * s * s;
    std::vector<std::array<double, 2>> half{{0.0, -kD}};
    for (int i = 0; i <= 12; ++i) {  // the bilge arc from the bottom to the side
      const double a = -0.5 * M_PI + 0.5 * M_PI * i / 12.0;
      half.push_back({f * (0.5 * kB - kR + kR * std::cos(a)), -kD + kR + kR * std::sin(a)});
    }
    half.push_back({f * 0.5 * kB, 0.0});
    out.push_back({x, kL / kStations, sk::PanelSymmetricSection(half, 24)});
  }
  return out;
}

}  // namespace

TEST_CASE("roll damping: the beam-sea roll peak of a ship-like hull is finite and smaller with it") {
  const auto stations = RoundBilgeHull();
  const double rho = 1025.0, g = 9.81;
  const sk::ObliqueHydrostatics hs = sk::ObliqueStationHydrostatics(stations, 0.5 * kL);
  sk::ObliqueMassProperties m;
  m.mass_kg = rho * hs.volume_m3;
  m.x_g_m = 0.5 * kL;
  m.z_g_m = 0.0;  // KG at the waterline
  m.inertia_kg_m2.diagonal() << m.mass_kg * std::pow(0.35 * kB, 2), m.mass_kg * std::pow(0.25 * kL, 2),
      m.mass_kg * std::pow(0.25 * kL, 2);
  sk::ObliqueStripOptions off;
  off.rho_kg_m3 = rho;
  off.g_m_s2 = g;
  sk::ObliqueStripOptions on = off;
  on.roll_damping = Ikeda(5.0);
  sk::RollDampingHull& h = on.roll_damping_hull;
  h.length_m = kL;
  h.breadth_m = kB;
  h.draught_m = kD;
  h.block_coefficient = hs.volume_m3 / (kL * kB * kD);
  h.midship_coefficient = 1.0 - (4.0 - M_PI) * kR * kR / (kB * kD);
  h.og_m = 0.0;
  std::vector<double> omegas;
  for (double w = 2.0; w <= 6.0 + 1e-9; w += 0.05) omegas.push_back(w);
  const auto r_off = sk::SolveObliqueStripTheory(stations, m, omegas, {90.0}, off);
  const auto r_on = sk::SolveObliqueStripTheory(stations, m, omegas, {90.0}, on);
  double peak_off = 0.0, peak_on = 0.0, w_peak = 0.0, b_visc = 0.0, b_pot = 0.0;
  for (std::size_t f = 0; f < omegas.size(); ++f) {
    const double a = std::abs(r_off.Wave(0, f).rao[3]);
    if (a > peak_off) {
      peak_off = a;
      w_peak = omegas[f];
      b_visc = r_on.Wave(0, f).viscous_roll_damping;
      b_pot = r_off.Wave(0, f).damping(3, 3);
    }
    peak_on = std::max(peak_on, std::abs(r_on.Wave(0, f).rao[3]));
    CHECK(r_off.Wave(0, f).viscous_roll_damping == 0.0);
    // Heave is not coupled to roll on a port-starboard symmetric hull: unchanged to rounding.
    CHECK(std::abs(r_on.Wave(0, f).rao[2] - r_off.Wave(0, f).rao[2]) <= 1e-9 * std::abs(r_off.Wave(0, f).rao[2]));
  }
  std::printf("round-bilge hull (Cb %.3f, Cm %.3f, B/d %.2f), beam seas, U = 0: roll peak %.3f rad/rad at %.2f rad/s "
              "with potential damping only (B44 %.3g N m s), %.3f with Ikeda's viscous part (B44 + %.3g N m s)\n",
              h.block_coefficient, h.midship_coefficient, kB / kD, peak_off, w_peak, b_pot, peak_on, b_visc);
  CHECK(std::isfinite(peak_on));
  CHECK(b_visc > 0.0);
  CHECK(peak_on < peak_off);
  CHECK(peak_off > 1.0);  // the scan straddles a resonance (the roll RAO per wave slope passes 1 there)
}
