// The 2D+t method's validity range against its defining conditions, evaluated independently: at the lowest
// Froude number the transverse wave length 2πU²/g equals the hull length; at the longest valid λ/L the
// encounter parameter τ = U ω_e / g equals 1/4 (ω from the deep-water dispersion relation, ω_e = ω + ω²U/g).
#include <catch2/catch.hpp>
#include <cmath>

#include "seakeeping/motions/validity_range.h"

using namespace hullopt;

TEST_CASE("lowest Froude number: transverse wave as long as the hull") {
  const double g = 9.81, L = 66.0;
  const double U = sk::MinValidFroudeNumber() * std::sqrt(g * L);
  CHECK(2 * M_PI * U * U / g == Approx(L).epsilon(1e-14));
}

TEST_CASE("longest valid wave: tau = 1/4 at the limit, above it inside, below it outside") {
  const double g = 9.81, L = 50.0;
  for (double Fn : {0.1, 0.4, 0.8, 1.2}) {
    const double U = Fn * std::sqrt(g * L);
    auto tau = [&](double lambda_over_L) {
      const double w = std::sqrt(2 * M_PI * g / (lambda_over_L * L));
      return U * (w + w * w * U / g) / g;
    };
    const double lim = sk::MaxValidLambdaOverL(Fn);
    CHECK(tau(lim) == Approx(0.25).epsilon(1e-12));
    CHECK(tau(0.99 * lim) > 0.25);
    CHECK(tau(1.01 * lim) < 0.25);
  }
  CHECK(sk::MaxValidLambdaOverL(0.8) == Approx(93.75).epsilon(1e-3));  // 146.48 Fn^2, as documented
}

TEST_CASE("warnings name the rule, and there are none inside the range") {
  const double g = 9.81, L = 66.0;
  const std::vector<double> omega = {0.2, 0.5, 1.0, 3.0};  // λ/L 23.4, 3.7, 0.93, 0.10
  CHECK(sk::ValidityWarnings(0.8 * std::sqrt(g * L), L, g, omega).empty());
  const auto w = sk::ValidityWarnings(0.1 * std::sqrt(g * L), L, g, omega);
  REQUIRE(w.size() == 2);
  CHECK(w[0].find("Fn 0.1 is below the validity range") == 0);
  CHECK(w[1].find("2 of 4 wave frequencies have lambda/L above 1.46") == 0);  // 146.48 * 0.01
}
