// Zero-speed strip theory in oblique seas against a 3D panel method: Capytaine v2.3.1 on the parabolic
// Wigley hull (L 3 m, B 0.3 m, T 0.1875 m) at KG 0.17 m (GM_T < 0) and KG 0.13 m (stable),
// data/peers-oblique/ (its conventions are the solver's: docs/conventions.md). Radiation coefficients about the
// CG, excitation and RAO amplitudes at 90°, 135° and 180° over ω = 2–9 rad/s.
//
// Measure: the largest difference over a band of frequencies as a fraction of the Capytaine curve's largest
// value (a zero crossing does not blow it up). Bands: all ω (2–9 rad/s, λ/L = 5.1–0.25) and short waves
// (ω >= 5 rad/s, λ <= 0.82 L), where strip theory's slender-body assumption (kL >> 1) holds. Quantities that
// vanish by symmetry (head-sea sway, roll and yaw; beam-sea pitch and yaw of this fore–aft symmetric hull)
// are exact zeros here and Capytaine noise there: not compared (test_oblique_strip_symmetry checks them).
// The table is printed; docs/validation.md quotes it.
#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "seakeeping/motions/oblique_strip_theory.h"
#include "support/data_table.h"
#include "support/wigley_oblique.h"

using namespace hullopt;

namespace {

constexpr double kRho = 1000.0, kG = 9.81;
constexpr double kShortWaveOmega = 5.0;  // [rad/s] start of the short-wave band
// 40 stations of 20 panels: with 80 stations of 32 panels every figure of the table moves by 1.5 points or
// less (docs/validation.md), far below the strip-theory differences measured.
constexpr int kSections = 40, kPanels = 20;

// Tolerances (from the strip-theory literature, confirmed by the comparison printed above them; not fitted):
// Heave and pitch in short waves: 2D sections are right where kL >> 1, the ends' 3D relief is ~10 % (A33
// 11.6 %, B33 4 %, B55 10 % measured).
constexpr double kHeavePitchShort = 0.15;
// Pitch added mass in short waves: the 3D A55 keeps a hump up to λ ≈ 0.8 L (ω = 5 rad/s: 19.1 kg m² against
// the sections' 11.2) that 2D sections lack; at ω >= 6.5 rad/s it is within 13 % (42 % measured at ω = 5).
constexpr double kPitchAddedMassShort = 0.5;
// Sway, roll and yaw radiation in short waves: the 3D flow round the ends reduces the lateral damping (B22 up
// to +21 %, B66 up to +93 % locally at ω = 5), and B44 about a CG above the keel is a small difference of
// larger terms (b44 + 2 z_G b24 + z_G² b22), so its error is that of B22 and B24 magnified (60 % at KG 0.17).
constexpr double kLateralShort = 0.7;
// Excitation over every ω: FK dominates in long waves and the Haskind diffraction is right in short ones;
// between, the missing 3D diffraction (|F4|, |F5|, |F6| at 135°) is up to ~20 % of the curve's maximum.
constexpr double kExcitation = 0.25;
// Froude–Krylov as complex numbers over every ω: the same pressure integral in both codes; the panelled volume
// (−0.28 %) and the midpoint rule over 40 stations of a wave down to 0.25 L long (kΔx = 0.6 at 9 rad/s: O((kΔx)²/24)
// = 1.5 %): 3 %.
constexpr double kFroudeKrylov = 0.03;
// Excitation as complex numbers (amplitude and phase) over every ω: the phase of the missing 3D diffraction
// adds to the amplitude error (28.5 % measured at worst, |F4| at 135°, KG 0.17).
constexpr double kExcitationComplex = 0.5;
// RAOs off the roll resonance, except roll: the motions are mass- and stiffness-dominated; the heave/pitch
// resonance near 6–7 rad/s is damped by B33/B55, which agree within 10 % in short waves. Measured: 6.0 % at
// worst (sway at 135°, KG 0.13).
constexpr double kRao = 0.1;
// Roll RAO off the resonance: F4/(C44 − ω²(I44 + A44) + iωB44) with the lateral coefficients' errors (26 % at
// KG 0.17, 135°). At the KG 0.13 roll resonance (4.3–4.7 rad/s) only the potential roll damping B44 limits the
// peak, a few 1e-2 N m s whose 3D value strip theory over-predicts: the peak is printed, not bounded.
constexpr double kRollRao = 0.35;


struct Run {
  // [rad/s] a band left out of the RAO measure "off resonance" (the KG 0.13 roll resonance), or empty.
  double resonance_lo = 0.0, resonance_hi = 0.0;
  double kg = 0.0;  // [m]
  test::NamedDataTable radiation, excitation, rao, stiffness;
  std::vector<double> omegas;
  sk::ObliqueStripResult ours;
};

Run Solve(const std::string& prefix, double kg, double resonance_lo = 0.0, double resonance_hi = 0.0) {
  Run r;
  r.resonance_lo = resonance_lo;
  r.resonance_hi = resonance_hi;
  r.kg = kg;
  r.radiation = test::ReadNamedDataTable("peers-oblique/" + prefix + "_radiation.csv");
  r.excitation = test::ReadNamedDataTable("peers-oblique/" + prefix + "_excitation.csv");
  r.rao = test::ReadNamedDataTable("peers-oblique/" + prefix + "_rao.csv");
  r.stiffness = test::ReadNamedDataTable("peers-oblique/" + prefix + "_mass_stiffness.csv");
  REQUIRE(!r.radiation.rows.empty());
  REQUIRE(!r.excitation.rows.empty());
  REQUIRE(!r.rao.rows.empty());
  REQUIRE(r.stiffness.rows.size() == 6);
  for (const auto& row : r.radiation.rows) r.omegas.push_back(row[0]);
  sk::ObliqueStripOptions o;
  o.rho_kg_m3 = kRho;
  o.g_m_s2 = kG;
  r.ours = sk::SolveObliqueStripTheory(test::WigleyObliqueStations(kSections, kPanels),
                                       test::WigleyObliqueMass(kg), r.omegas, {90.0, 135.0, 180.0}, o);
  return r;
}

// The band errors of one curve: every ω, short waves, and every ω outside the run's resonance band.
struct Misfit {
  double all = 0.0, short_waves = 0.0, off_resonance = 0.0;
};

Misfit CurveMisfit(const Run& r, const std::vector<double>& ours, const std::vector<double>& theirs) {
  std::array<double, 3> num{}, den{};
  for (std::size_t i = 0; i < ours.size(); ++i) {
    const double w = r.omegas[i];
    const std::array<bool, 3> in{true, w >= kShortWaveOmega, !(w > r.resonance_lo && w < r.resonance_hi)};
    for (int b = 0; b < 3; ++b)
      if (in[b]) {
        num[b] = std::max(num[b], std::fabs(ours[i] - theirs[i]));
        den[b] = std::max(den[b], std::fabs(theirs[i]));
      }
  }
  return {num[0] / den[0], num[1] / den[1], num[2] / den[2]};
}

void Print(const std::string& name, const Misfit& m, const std::vector<double>& omegas,
           const std::vector<double>& ours, const std::vector<double>& theirs) {
  std::printf("  %-10s all %5.1f %%  short %5.1f %%  off-res. %5.1f %%  ours/Capytaine:", name.c_str(),
              100 * m.all, 100 * m.short_waves, 100 * m.off_resonance);
  for (std::size_t f = 0; f < omegas.size(); ++f)
    if (std::fmod(omegas[f], 1.5) == 0.5) std::printf("  %.1f: %.4g/%.4g", omegas[f], ours[f], theirs[f]);
  std::printf("\n");
}

std::string RadiationUnit(int i, int j, bool damping) {
  const int rot = (i >= 4) + (j >= 4);
  if (damping) return rot == 0 ? "N_s_per_m" : rot == 1 ? "N_s" : "N_m_s";
  return rot == 0 ? "kg" : rot == 1 ? "kg_m" : "kg_m2";
}

Misfit Radiation(const Run& r, int i, int j, bool damping) {
  const std::string name = std::string(damping ? "B" : "A") + std::to_string(i) + std::to_string(j);
  const int c = r.radiation.Column(name + "_" + RadiationUnit(i, j, damping));
  REQUIRE(c >= 0);
  std::vector<double> ours, theirs;
  for (std::size_t f = 0; f < r.omegas.size(); ++f) {
    const auto& fr = r.ours.frequencies[f];
    ours.push_back(damping ? fr.damping(i - 1, j - 1) : fr.added_mass(i - 1, j - 1));
    theirs.push_back(r.radiation.rows[f][c]);
  }
  const Misfit m = CurveMisfit(r, ours, theirs);
  Print(name, m, r.omegas, ours, theirs);
  return m;
}

std::size_t HeadingIndex(double heading) { return heading == 90.0 ? 0 : heading == 135.0 ? 1 : 2; }

// Amplitudes of a per-(heading, ω) table's column against ours, matched by heading and ω. With `complex_misfit`,
// also the largest |X_ours − X_theirs| / max |X_theirs| of the complex values (the phase column beside it): the
// check of the phase conventions.
enum class Part { kTotal, kFk, kMotion };

Misfit PerWave(const Run& r, const test::NamedDataTable& t, const std::string& column, double heading, int dof,
               Part part, const std::string& label, double* complex_misfit = nullptr) {
  const int c = t.Column(column);
  const int cp = t.Column(column.substr(0, column.find("_amp_")) + "_phase_deg");
  REQUIRE(c >= 0);
  REQUIRE(cp >= 0);
  std::vector<double> ours, theirs;
  double num = 0.0, den = 0.0;
  for (std::size_t f = 0; f < r.omegas.size(); ++f) {
    const auto row = std::find_if(t.rows.begin(), t.rows.end(), [&](const std::vector<double>& v) {
      return v[0] == heading && std::fabs(v[1] - r.omegas[f]) < 1e-9;
    });
    REQUIRE(row != t.rows.end());
    const auto& w = r.ours.Wave(HeadingIndex(heading), f);
    const std::complex<double> x = part == Part::kMotion            ? w.rao[dof - 1]
                                   : part == Part::kFk ? w.froude_krylov[dof - 1]
                                                                 : w.excitation[dof - 1];
    ours.push_back(std::abs(x));
    theirs.push_back((*row)[c]);
    num = std::max(num, std::abs(x - std::polar((*row)[c], (*row)[cp] * M_PI / 180.0)));
    den = std::max(den, (*row)[c]);
  }
  const Misfit m = CurveMisfit(r, ours, theirs);
  Print(label, m, r.omegas, ours, theirs);
  if (complex_misfit) {
    *complex_misfit = num / den;
    std::printf("  %-10s complex (amplitude and phase), all: %5.1f %%\n", label.c_str(), 100 * num / den);
  }
  return m;
}

Misfit Excitation(const Run& r, int i, double heading) {
  const std::string column = "F" + std::to_string(i) + "_exc_amp_" + (i >= 4 ? "N_m_per_m" : "N_per_m");
  double complex_misfit = 0.0;
  const Misfit m = PerWave(r, r.excitation, column, heading, i, Part::kTotal,
                           "|F" + std::to_string(i) + "| " + std::to_string(static_cast<int>(heading)),
                           &complex_misfit);
  // The phases: a sign or origin slip in the wave phase, the axes or the e^{iωt} convention would make the
  // complex difference of the order of the amplitude itself (100–200 %); the strip-theory amplitude and phase
  // errors together stay below kExcitationComplex.
  CHECK(complex_misfit < kExcitationComplex);
  return m;
}

// Froude–Krylov: the incident pressure integrated over the hull in both codes (the strip sum exactly for sway,
// heave and roll; pitch and yaw with the longitudinal-slope moment), so only the discretisations differ.
// Roll about the CG, F4 = F4(waterline) + z_G F2, is a difference of larger terms at KG 0.17 (z_G F2 ≈ 51 N m
// against |F4| <= 14 at 8 rad/s): its misfit is taken relative to max |F4| + |z_G| max |F2|, the size of the
// terms it is made of.
double FroudeKrylov(const Run& r, int i, double heading) {
  const auto column = [](int d) {
    return "F" + std::to_string(d) + "_FK_amp_" + (d >= 4 ? "N_m_per_m" : "N_per_m");
  };
  double complex_misfit = 0.0;
  PerWave(r, r.excitation, column(i), heading, i, Part::kFk,
          "FK" + std::to_string(i) + " " + std::to_string(static_cast<int>(heading)), &complex_misfit);
  if (i != 4) return complex_misfit;
  const int c4 = r.excitation.Column(column(4)), c2 = r.excitation.Column(column(2));
  double f4 = 0.0, f2 = 0.0;
  for (const auto& row : r.excitation.rows)
    if (row[0] == heading) f4 = std::max(f4, row[c4]), f2 = std::max(f2, row[c2]);
  const double z_g = test::WigleyObliqueMass(r.kg).z_g_m;
  const double misfit = complex_misfit * f4 / (f4 + std::fabs(z_g) * f2);
  std::printf("  FK4 %3.0f    complex, relative to max|F4| + |z_G| max|F2|: %5.1f %%\n", heading, 100 * misfit);
  return misfit;
}

Misfit Rao(const Run& r, int i, double heading) {
  static const char* const kName[] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};
  const std::string column = std::string(kName[i - 1]) + (i >= 4 ? "_amp_rad_per_rad" : "_amp_m_per_m");
  return PerWave(r, r.rao, column, heading, i, Part::kMotion,
                 std::string(kName[i - 1]) + " " + std::to_string(static_cast<int>(heading)));
}

// Restoring: ours from the panelled sections, the data's from the closed-form hydrostatics.
void CheckRestoring(const Run& r) {
  for (const auto& row : r.stiffness.rows) {
    const int i = static_cast<int>(row[0]) - 1, j = static_cast<int>(row[1]) - 1;
    std::printf("  C%d%d ours %.6g, data %.6g\n", i + 1, j + 1, r.ours.restoring(i, j), row[3]);
    // The hydrostatics test bounds the panelled volume and waterplane moments to 5e-3; C44 = ρg(I_T + V(z_B −
    // z_G)) is a difference of such terms, so its error is 5e-3 of ρg(I_T + |V z_B|).
    constexpr double kHydrostatics = 5e-3;
    const double scale = i == 3 ? kRho * kG * (r.ours.hydrostatics.waterplane_i_t_m4 +
                                               std::fabs(r.ours.hydrostatics.volume_m3 * r.ours.hydrostatics.z_b_m))
                                : std::fabs(row[3]);
    CHECK(std::fabs(r.ours.restoring(i, j) - row[3]) <= kHydrostatics * scale + 1e-9);
  }
}

void Compare(const Run& r) {
  std::printf("  quantity       largest difference / curve maximum (ω = 2-9, and short waves ω >= %.0f)\n",
              kShortWaveOmega);
  CHECK(Radiation(r, 3, 3, false).short_waves < kHeavePitchShort);
  CHECK(Radiation(r, 3, 3, true).short_waves < kHeavePitchShort);
  CHECK(Radiation(r, 5, 5, false).short_waves < kPitchAddedMassShort);
  CHECK(Radiation(r, 5, 5, true).short_waves < kHeavePitchShort);
  for (int d : {2, 4, 6})
    for (bool b : {false, true}) CHECK(Radiation(r, d, d, b).short_waves < kLateralShort);
  for (bool b : {false, true}) CHECK(Radiation(r, 2, 4, b).short_waves < kLateralShort);
  for (int d : {2, 3, 4}) CHECK(Excitation(r, d, 90.0).all < kExcitation);
  for (int d : {2, 3, 4, 5, 6}) CHECK(Excitation(r, d, 135.0).all < kExcitation);
  for (int d : {3, 5}) CHECK(Excitation(r, d, 180.0).all < kExcitation);
  for (int d : {2, 3, 4}) CHECK(FroudeKrylov(r, d, 90.0) < kFroudeKrylov);
  for (int d : {2, 3, 4, 5, 6}) CHECK(FroudeKrylov(r, d, 135.0) < kFroudeKrylov);
  for (int d : {3, 5}) CHECK(FroudeKrylov(r, d, 180.0) < kFroudeKrylov);
  for (double h : {90.0, 135.0}) CHECK(Rao(r, 4, h).off_resonance < kRollRao);
  for (int d : {2, 3}) CHECK(Rao(r, d, 90.0).off_resonance < kRao);
  for (int d : {2, 3, 5, 6}) CHECK(Rao(r, d, 135.0).off_resonance < kRao);
  for (int d : {3, 5}) CHECK(Rao(r, d, 180.0).off_resonance < kRao);
  if (r.resonance_hi > 0) {
    // The roll resonance peak in beam seas: largest roll RAO in the band, ours and Capytaine's.
    const int c = r.rao.Column("roll_amp_rad_per_rad");
    double ours = 0.0, theirs = 0.0, w_ours = 0.0, w_theirs = 0.0;
    for (std::size_t f = 0; f < r.omegas.size(); ++f) {
      const double a = std::abs(r.ours.Wave(0, f).rao[3]);
      if (a > ours) ours = a, w_ours = r.omegas[f];
    }
    for (const auto& row : r.rao.rows)
      if (row[0] == 90.0 && row[c] > theirs) theirs = row[c], w_theirs = row[1];
    std::printf("  beam-sea roll peak: ours %.3g per kA at %.2f rad/s, Capytaine %.3g at %.2f rad/s\n", ours,
                w_ours, theirs, w_theirs);
  }
  CheckRestoring(r);
}

}  // namespace

TEST_CASE("oblique strip theory against Capytaine, Wigley KG 0.17 m") {
  std::printf("Wigley KG 0.17 m, %d stations x %d panels\n", kSections, kPanels);
  Compare(Solve("wigley", 0.17));
}

TEST_CASE("oblique strip theory against Capytaine, Wigley KG 0.13 m") {
  std::printf("Wigley KG 0.13 m, %d stations x %d panels\n", kSections, kPanels);
  Compare(Solve("wigley_kg0.13", 0.13, 4.0, 5.0));
}
