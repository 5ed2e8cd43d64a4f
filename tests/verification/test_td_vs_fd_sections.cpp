// Time-domain heave added mass and damping against the independent frequency-domain panel solver (issue 3,
// "what it must show" 2 and 3). The frequency-domain solver (seakeeping/frequency_domain_section.h, branch
// fdomain) evaluates the pulsating-source Green function directly; the time-domain values come from the
// transient kernel's memory summed to the periodic steady state. Same panels in both, and the
// frequency-domain lid is switched off: both then carry the source formulation's irregular frequency, so the
// bands around it (semicircle and rectangle ω²(B/2)/g ≈ 1.75, Lewis ≈ 2.0) are excluded — the time domain has
// no lid (docs/theory.md). Criterion of the issue: each difference within 2% of the local value or 1% of the
// curve's peak, whichever is larger. Measured (14 panels): within 1.5% local at the remaining 12 frequencies.
// Compiles to a skipped placeholder until the frequency-domain solver is merged.
#include <catch2/catch.hpp>

#if __has_include("seakeeping/frequency_domain_section.h")
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "seakeeping/frequency_domain_section.h"
#include "seakeeping/section_shapes.h"
#include "seakeeping/td_heave_coefficients.h"

using namespace hullopt::sk;

namespace {
constexpr double kG = 9.81;
constexpr double kRho = 1025.0;
constexpr double kTolLocal = 0.02;  // issue 3
constexpr double kTolPeak = 0.01;   // issue 3

void Compare(const std::string& name, const std::vector<std::vector<Panel>>& sections, double half_beam,
             double irregular) {
  std::vector<double> k, w;
  for (double kk : {0.1, 0.25, 0.4, 0.5, 0.6, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5, 2.75, 3.0})
    if (std::fabs(kk - irregular) > 0.26) k.push_back(kk), w.push_back(std::sqrt(kk * kG / half_beam));
  REQUIRE(k.size() >= 10);
  std::vector<Panel> all;
  for (const auto& s : sections) all.insert(all.end(), s.begin(), s.end());
  FrequencyDomainOptions fo;
  fo.rho_kg_m3 = kRho, fo.g_m_s2 = kG, fo.lid_panels = 0;
  const auto fd = SolveSectionFrequencyDomain(sections, w, fo);
  const auto td = TimeDomainHeaveCoefficients(all, w, kRho, kG);
  double a_peak = 0, b_peak = 0;
  for (const auto& h : fd)
    a_peak = std::max(a_peak, std::fabs(h.a33())), b_peak = std::max(b_peak, std::fabs(h.b33()));
  for (std::size_t i = 0; i < w.size(); ++i) {
    INFO(name << " at w^2(B/2)/g = " << k[i] << ": a33 TD " << td.a33_kg_per_m[i] << " FD " << fd[i].a33()
              << ", b33 TD " << td.b33_kg_per_m_s[i] << " FD " << fd[i].b33());
    CHECK(std::fabs(td.a33_kg_per_m[i] - fd[i].a33()) <=
          std::max(kTolLocal * std::fabs(fd[i].a33()), kTolPeak * a_peak));
    CHECK(std::fabs(td.b33_kg_per_m_s[i] - fd[i].b33()) <=
          std::max(kTolLocal * std::fabs(fd[i].b33()), kTolPeak * b_peak));
  }
}
}  // namespace

TEST_CASE("semicircle: time domain against frequency domain", "[td][fd][verification]") {
  Compare("semicircle", {PanelSymmetricSection(SemicircleContour(1.0), 14)}, 1.0, 1.75);
}

TEST_CASE("Lewis, rectangle and two semicircles: time domain against frequency domain", "[.][td][fd]") {
  Compare("lewis B/T 2 sigma 0.6", {PanelSymmetricSection(LewisContour(2.0, 1.0, 0.6), 14)}, 1.0, 2.0);
  Compare("rectangle B/T 2", {PanelSymmetricSection(RectangleContour(2.0, 1.0), 14)}, 1.0, 1.75);
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
