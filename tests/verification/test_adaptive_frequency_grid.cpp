// The adaptive frequency grid (evaluation/adaptive_frequency_grid.h) on a one-degree-of-freedom oscillator,
// whose response is known in closed form: |X| = 1/√((1−r²)² + (2ζr)²), r = ω/ω_n, peak 1/(2ζ√(1−ζ²)) at
// r = √(1−2ζ²). From a coarse grid that steps over the peak the refinement finds the peak within the
// under-sampling tolerance and the MSI of a sea around it within the MSI tolerance of a dense sampling of the
// closed form; with refinement off the grid is solved as given; the caps stop it with a warning that names the
// key to raise.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>

#include "evaluation/adaptive_frequency_grid.h"
#include "seakeeping/motions/rao_checks.h"

using namespace hullopt;

namespace {
constexpr double kOmegaN = 1.0;  // [rad/s] natural frequency
constexpr double kZeta = 0.02;   // damping ratio: half-power width 2ζω_n = 0.04 rad/s
constexpr double kG = 9.81;

std::complex<double> Oscillator(double w, double zeta) {
  const double r = w / kOmegaN;
  return 1.0 / std::complex<double>(1 - r * r, 2 * zeta * r);
}

double ClosedFormPeak(double zeta) { return 1.0 / (2 * zeta * std::sqrt(1 - zeta * zeta)); }

// Heave: the oscillator; pitch zero; zero speed (ω_e = ω).
sk::RaoTable OscillatorTable(const std::vector<double>& w, double zeta) {
  sk::RaoTable t;
  t.g_m_s2 = kG;
  for (double x : w) {
    t.omega_rad_s.push_back(x);
    t.omega_e_rad_s.push_back(x);
    t.heave.push_back(Oscillator(x, zeta));
    t.pitch.push_back(0.0);
  }
  return t;
}

std::vector<double> Uniform(double from, double to, int n) {
  std::vector<double> w(n);
  for (int i = 0; i < n; ++i) w[i] = from + (to - from) * i / (n - 1);
  return w;
}

// A coarse grid: 30 frequencies 0.2..3 rad/s, step 0.097 rad/s, 2.4 half-power widths: the largest sample
// (at 0.972 rad/s) is 2.1 half-widths from the peak, far below it.
const std::vector<double> kCoarse = Uniform(0.2, 3.0, 30);

bool HasUnderSampled(const std::vector<std::string>& w) {
  for (const auto& s : w)
    if (s.find("under-sampled") != std::string::npos) return true;
  return false;
}
}  // namespace

TEST_CASE("the refinement finds a one-degree-of-freedom peak from a coarse grid", "[adaptive_grid]") {
  const double peak = ClosedFormPeak(kZeta);  // 25.005
  REQUIRE(HasUnderSampled(sk::RaoResonanceWarnings(OscillatorTable(kCoarse, kZeta))));
  int calls = 0;
  const eval::AdaptiveGridOptions o;
  const auto r = eval::RefineFrequencyGrid(
      kCoarse,
      [&](const std::vector<double>& w) {
        ++calls;
        return OscillatorTable(w, kZeta);
      },
      o);
  CHECK(r.converged);
  CHECK(r.passes >= 1);
  CHECK(calls == r.passes + 1);  // one solve per pass: only the inserted frequencies
  CHECK(r.rao.warnings.empty());
  CHECK_FALSE(HasUnderSampled(sk::RaoResonanceWarnings(r.rao)));
  const sk::RaoPeakFit f = sk::FitRaoPeak(r.rao.omega_rad_s, r.rao.heave);
  // The fitted peak and the largest sample both within the peak tolerance of the closed form.
  CHECK(std::abs(f.fitted - peak) / peak < o.peak_tolerance);
  CHECK(std::abs(f.sampled - peak) / peak < o.peak_tolerance);
  CHECK(std::abs(f.omega_fitted - kOmegaN * std::sqrt(1 - 2 * kZeta * kZeta)) < 2 * kZeta * kOmegaN);
  // Inserted locally: far fewer frequencies than a uniform grid at the final spacing near the peak.
  CHECK(r.rao.omega_rad_s.size() < 60);
  for (std::size_t i = 1; i < r.rao.omega_rad_s.size(); ++i) REQUIRE(r.rao.omega_rad_s[i] > r.rao.omega_rad_s[i - 1]);
}

TEST_CASE("with a sea, the MSI of the refined grid matches a dense sampling of the closed form", "[adaptive_grid]") {
  // A JONSWAP sea peaking near the resonance (Tz 5.5 s: ω_p ≈ 0.88 rad/s) so the integrand has the sharp peak.
  eval::GridSeas seas;
  seas.spectra = sk::BuildSpectra({sk::SeaState::JonswapTz(1.0, 5.5)});
  seas.hull = {10.0, 10.0};
  const eval::AdaptiveGridOptions o;
  const auto solve = [](const std::vector<double>& w) { return OscillatorTable(w, kZeta); };
  const auto r = eval::RefineFrequencyGrid(kCoarse, solve, o, &seas);
  CHECK(r.converged);
  // Reference: the closed form sampled every 0.0005 rad/s (80 samples per half-power width).
  const sk::RaoTable dense = OscillatorTable(Uniform(0.2, 3.0, 5601), kZeta);
  const auto ref = sk::EvaluateDesign(dense, seas.hull, seas.spectra, {}, {});
  const auto got = sk::EvaluateDesign(r.rao, seas.hull, seas.spectra, {}, {});
  const auto coarse = sk::EvaluateDesign(OscillatorTable(kCoarse, kZeta), seas.hull, seas.spectra, {}, {});
  // Tolerance: twice the pass-to-pass MSI tolerance, as the change of the last pass bounds the error left only
  // roughly (the error of a converging sequence is of the order of its last step).
  constexpr double kMsiAgreement = 2 * 0.05;
  for (std::size_t p = 0; p < ref.seas[0].positions.size(); ++p) {
    const double m_ref = ref.seas[0].positions[p].msi_pct, m = got.seas[0].positions[p].msi_pct;
    INFO("position " << p << ": MSI refined " << m << " dense " << m_ref << " coarse "
                     << coarse.seas[0].positions[p].msi_pct);
    CHECK(std::abs(m - m_ref) < kMsiAgreement);
  }
  // The coarse grid alone misses the MSI by more (the test has teeth).
  CHECK(std::abs(coarse.seas[0].positions[1].msi_pct - ref.seas[0].positions[1].msi_pct) > kMsiAgreement);
}

TEST_CASE("refinement off solves the given grid once", "[adaptive_grid]") {
  eval::AdaptiveGridOptions o;
  o.enabled = false;
  int calls = 0;
  const auto r = eval::RefineFrequencyGrid(
      kCoarse,
      [&](const std::vector<double>& w) {
        ++calls;
        return OscillatorTable(w, kZeta);
      },
      o);
  CHECK(calls == 1);
  CHECK(r.rao.omega_rad_s == kCoarse);
  CHECK(r.passes == 0);
}

TEST_CASE("the caps stop the refinement with a warning naming the key", "[adaptive_grid]") {
  const auto solve = [](const std::vector<double>& w) { return OscillatorTable(w, 1e-5); };  // nearly undamped
  eval::AdaptiveGridOptions o;
  o.max_frequencies = 36;
  auto r = eval::RefineFrequencyGrid(kCoarse, solve, o);
  CHECK_FALSE(r.converged);
  CHECK(r.rao.omega_rad_s.size() <= 36u);
  REQUIRE(r.rao.warnings.size() == 1);
  CHECK_THAT(r.rao.warnings[0], Catch::Contains("raise solver.adaptive_grid_max_frequencies"));
  o.max_frequencies = 400;
  o.max_passes = 2;
  r = eval::RefineFrequencyGrid(kCoarse, solve, o);
  CHECK_FALSE(r.converged);
  CHECK(r.passes == 2);
  REQUIRE(r.rao.warnings.size() == 1);
  CHECK_THAT(r.rao.warnings[0], Catch::Contains("raise solver.adaptive_grid_max_passes"));
}

TEST_CASE("adaptive grid options are checked", "[adaptive_grid]") {
  std::string e;
  CHECK(eval::AdaptiveGridOptions{}.IsValid(&e));
  eval::AdaptiveGridOptions o;
  o.msi_tolerance_pct = 0.0;
  CHECK_FALSE(o.IsValid(&e));
  CHECK_THAT(e, Catch::Contains("msi_tolerance_pct"));
  o = {};
  o.max_passes = 0;
  CHECK_FALSE(o.IsValid(&e));
  CHECK_THAT(e, Catch::Contains("max_passes"));
  o = {};
  o.max_frequencies = 2;
  CHECK_FALSE(o.IsValid(&e));
  CHECK_THAT(e, Catch::Contains("max_frequencies"));
  o.enabled = true;
  CHECK_THROWS_AS(eval::RefineFrequencyGrid(kCoarse, [](const std::vector<double>& w) { return OscillatorTable(w, kZeta); }, o),
                  std::invalid_argument);
}
