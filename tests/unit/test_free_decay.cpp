// Free decay from frequency-domain coefficients against the closed form of a damped oscillator (constant a33,
// b33): x/x0 = e^{−ζω_n t}(cos ω_d t + ζ/sqrt(1 − ζ²) sin ω_d t).
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "support/free_decay.h"

TEST_CASE("free decay of a constant-coefficient oscillator", "[free_decay]") {
  // The Fourier integral is cut at 4× the last frequency (50 rad/s) where b33 is dropped: the neglected tail
  // ∫ sin(ωt)/ω³ dω·C/(m + a) is ~1e−4 of x0.
  constexpr double kTolDecay = 5e-4;
  hullopt::sk::FreeDecayInput in;
  const double m = 2.0, a = 1.0, b = 0.6, C = 3.0;
  for (int i = 1; i <= 500; ++i) {
    in.omega_rad_s.push_back(0.1 * i);
    in.a33_kg_per_m.push_back(a);
    in.b33_kg_per_m_s.push_back(b);
  }
  in.a33_infinite_kg_per_m = a;
  in.mass_kg_per_m = m;
  in.restoring_n_per_m2 = C;
  const std::vector<double> t = {0.0, 0.5, 1.0, 2.0, 4.0, 7.0};
  const auto x = hullopt::sk::FreeDecayFromCoefficients(in, t);
  const double wn = std::sqrt(C / (m + a)), zeta = b / (2 * (m + a) * wn),
               wd = wn * std::sqrt(1 - zeta * zeta);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double exact = std::exp(-zeta * wn * t[i]) *
                         (std::cos(wd * t[i]) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t[i]));
    CHECK(x[i] == Approx(exact).margin(kTolDecay));
  }
  in.mass_kg_per_m = 0;
  CHECK_THROWS_AS(hullopt::sk::FreeDecayFromCoefficients(in, t), std::invalid_argument);
}
