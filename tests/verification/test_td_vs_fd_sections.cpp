// Time-domain heave added mass and damping against the independent frequency-domain panel solver:
// semicircle, Lewis (B/T = 2, σ = 0.6), rectangle (B/T = 2) and two semicircles
// at centre spacing 3R heaving in phase. The frequency-domain solver (seakeeping/frequency_domain_section.h)
// evaluates the pulsating-source Green function directly; the time-domain values come from the transient
// kernel's memory summed to the periodic steady state. Same panels (14 per body) in both, and the
// frequency-domain lid is switched off: both then carry the source formulation's irregular frequency, and the
// band around it (semicircle and rectangle ω²(B/2)/g ≈ 1.75, Lewis ≈ 2.0) is excluded from the check — the
// time domain has no lid (docs/theory.md); what happens inside the band is printed. Acceptance:
// each difference within 2% of the local value or 1% of the curve's peak, whichever is larger, at 12
// frequencies from 0.1 to 3. Measured (14 panels per body): largest local difference a33 1.0, 0.9, 1.5, 21%
// (twin: near a zero of a33, within 0.22 of the peak allowance), b33 2.1, 1.2, 3.6, 2.0% (at the small
// high-frequency damping, within the peak allowance).
// Compiles to a skipped placeholder until the frequency-domain solver is merged.
#include <catch2/catch.hpp>

#if __has_include("seakeeping/sections/frequency_domain_section.h")
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "seakeeping/sections/frequency_domain_section.h"
#include "seakeeping/sections/section_shapes.h"
#include "seakeeping/strip/td_heave_coefficients.h"

using namespace hullopt::sk;

namespace {
constexpr double kG = 9.81;
constexpr double kRho = 1025.0;
constexpr double kTolLocal = 0.02;  // acceptance: 2% of the local value ...
constexpr double kTolPeak = 0.01;   // ... or 1% of the curve's peak, whichever is larger
// Half width in ω²(B/2)/g of the band around the source formulation's irregular frequency that is excluded
// from the check: the time domain has no lid, and its spurious resonance is a near-pole whose position
// (ω²R/g = 1.84, 1.88, 1.93 at 14, 28, 56 panels on the semicircle) and shape differ from those of the
// lid-off frequency-domain solver, so the two disagree there by O(1) (printed below). Outside ±0.26 both are
// back on the regular curve.
constexpr double kIrregularHalfBand = 0.26;

void Compare(const std::string& name, const std::vector<std::vector<Panel>>& sections, double half_beam,
             double irregular) {
  // Checked frequencies (at least 10 from 0.1 to 3 in ω²(B/2)/g), then a finer sampling of the irregular
  // band (reported only).
  std::vector<double> k, w;
  for (double kk : {0.1, 0.25, 0.4, 0.5, 0.6, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5, 2.75, 3.0})
    if (std::fabs(kk - irregular) > kIrregularHalfBand) k.push_back(kk);
  const std::size_t n_checked = k.size();
  REQUIRE(n_checked >= 10);
  for (int i = -5; i <= 5; ++i) k.push_back(irregular + 0.05 * i);
  for (double kk : k) w.push_back(std::sqrt(kk * kG / half_beam));
  std::vector<Panel> all;
  for (const auto& s : sections) all.insert(all.end(), s.begin(), s.end());
  FrequencyDomainOptions fo;
  fo.rho_kg_m3 = kRho, fo.g_m_s2 = kG, fo.lid_panels = 0;
  const auto fd = SolveSectionFrequencyDomain(sections, w, fo);
  fo.lid_panels = -1;
  const auto fd_lid = SolveSectionFrequencyDomain(sections, w, fo);
  const auto td = TimeDomainHeaveCoefficients(all, w, kRho, kG);
  double a_peak = 0, b_peak = 0;
  for (std::size_t i = 0; i < n_checked; ++i)
    a_peak = std::max(a_peak, std::fabs(fd[i].a33())), b_peak = std::max(b_peak, std::fabs(fd[i].b33()));
  // Largest difference relative to the local value, and the largest share of the allowance used.
  double a_rel = 0, b_rel = 0, a_use = 0, b_use = 0, k_a = 0, k_b = 0;
  for (std::size_t i = 0; i < n_checked; ++i) {
    INFO(name << " at w^2(B/2)/g = " << k[i] << ": a33 TD " << td.a33_kg_per_m[i] << " FD " << fd[i].a33()
              << ", b33 TD " << td.b33_kg_per_m_s[i] << " FD " << fd[i].b33());
    const double da = std::fabs(td.a33_kg_per_m[i] - fd[i].a33()),
                 db = std::fabs(td.b33_kg_per_m_s[i] - fd[i].b33());
    const double allow_a = std::max(kTolLocal * std::fabs(fd[i].a33()), kTolPeak * a_peak),
                 allow_b = std::max(kTolLocal * std::fabs(fd[i].b33()), kTolPeak * b_peak);
    if (da / std::fabs(fd[i].a33()) > a_rel) a_rel = da / std::fabs(fd[i].a33()), k_a = k[i];
    if (db / std::fabs(fd[i].b33()) > b_rel) b_rel = db / std::fabs(fd[i].b33()), k_b = k[i];
    a_use = std::max(a_use, da / allow_a), b_use = std::max(b_use, db / allow_b);
    CHECK(da <= allow_a);
    CHECK(db <= allow_b);
  }
  WARN(name << " (" << all.size() << " panels, " << n_checked
            << " frequencies outside the irregular band): largest |TD - FD| a33 " << 100 * a_rel
            << "% of local (at " << k_a << "), b33 " << 100 * b_rel << "% of local (at " << k_b
            << "); largest share of the allowance (2% local or 1% "
            << "of peak) a33 " << a_use << ", b33 " << b_use);
  // Inside the band (known limitation, not checked): worst difference against the lid-off and the lid-on
  // (irregular-frequency-free) frequency-domain values, in units of the curve's peak.
  double worst_a = 0, worst_b = 0, worst_a_lid = 0, worst_b_lid = 0, at_a = 0, at_b = 0;
  for (std::size_t i = n_checked; i < k.size(); ++i) {
    const double da = std::fabs(td.a33_kg_per_m[i] - fd[i].a33()) / a_peak,
                 db = std::fabs(td.b33_kg_per_m_s[i] - fd[i].b33()) / b_peak;
    if (da > worst_a) worst_a = da, at_a = k[i];
    if (db > worst_b) worst_b = db, at_b = k[i];
    worst_a_lid = std::max(worst_a_lid, std::fabs(td.a33_kg_per_m[i] - fd_lid[i].a33()) / a_peak);
    worst_b_lid = std::max(worst_b_lid, std::fabs(td.b33_kg_per_m_s[i] - fd_lid[i].b33()) / b_peak);
  }
  WARN(
      name << ", irregular band " << irregular << " +- 0.25 (11 frequencies, not checked): worst |TD - FD(no "
           << "lid)| a33 " << worst_a << " x peak at " << at_a << ", b33 " << worst_b << " x peak at " << at_b
           << "; worst |TD - FD(lid)| a33 " << worst_a_lid << " x peak, b33 " << worst_b_lid << " x peak");
}
}  // namespace

TEST_CASE("semicircle: time domain against frequency domain", "[td][fd][verification]") {
  Compare("semicircle", {PanelSymmetricSection(SemicircleContour(1.0), 14)}, 1.0, 1.75);
}

TEST_CASE("Lewis section: time domain against frequency domain", "[td][fd][verification]") {
  Compare("lewis B/T 2 sigma 0.6", {PanelSymmetricSection(LewisContour(2.0, 1.0, 0.6), 14)}, 1.0, 2.0);
}

TEST_CASE("rectangle: time domain against frequency domain", "[td][fd][verification]") {
  Compare("rectangle B/T 2", {PanelSymmetricSection(RectangleContour(2.0, 1.0), 14)}, 1.0, 1.75);
}

TEST_CASE("two semicircles at 3R heaving in phase: time domain against frequency domain",
          "[td][fd][verification]") {
  Compare("two semicircles at 3R",
          {PanelSymmetricSection(SemicircleContour(1.0), 14, -1.5),
           PanelSymmetricSection(SemicircleContour(1.0), 14, 1.5)},
          1.0, 1.75);
}
#else
TEST_CASE("time domain against frequency domain (solver not merged yet)", "[td][fd]") {
  WARN("seakeeping/frequency_domain_section.h not present: comparison skipped");
}
#endif
