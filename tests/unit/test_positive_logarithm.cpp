// The kernel's logarithm of positive normal numbers (fdlibm's algorithm) against std::log (glibc's, correctly
// rounded or nearly): within 1 ulp of the result (fdlibm's bound) over 2^−1022 .. 2^1023 and around 1 and the
// reduction's break point √2; and the four-value AVX form bitwise the one-value form (the same operations).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "seakeeping/green/positive_logarithm.h"

using hullopt::sk::PositiveLogarithm;

namespace {
double Ulps(double x) {
  const double ref = std::log(x);
  return std::fabs(PositiveLogarithm(x) - ref) / std::fabs(std::nextafter(ref, 2.0 * ref + 1.0) - ref);
}

std::vector<double> Samples() {
  std::vector<double> x;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> exponent(-1022.0, 1023.0), near_one(0.5, 2.0);
  for (int i = 0; i < 100000; ++i) x.push_back(std::exp2(exponent(rng)));
  for (int i = 0; i < 100000; ++i) x.push_back(near_one(rng));
  for (double v : {1.0, std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0), 1.4142135623730951,
                   std::nextafter(1.4142135623730951, 2.0), std::nextafter(1.4142135623730951, 0.0), 2.0,
                   0.7071067811865476, 0x1p-1022, 0x1.fffffffffffffp1023, 9.81 / 4.0})
    x.push_back(v);
  return x;
}
}  // namespace

TEST_CASE("PositiveLogarithm: within 1 ulp of std::log", "[unit][transient_green]") {
  constexpr double kUlps = 1.0;  // fdlibm's bound for its algorithm
  CHECK(PositiveLogarithm(1.0) == 0.0);
  CHECK(PositiveLogarithm(2.0) == std::log(2.0));
  double worst = 0.0;
  for (double x : Samples())
    if (x != 1.0) worst = std::fmax(worst, Ulps(x));
  INFO("worst " << worst << " ulp");
  CHECK(worst <= kUlps);
}

#if defined(__x86_64__) && defined(__GNUC__)
TEST_CASE("PositiveLogarithmAvx: bitwise the one-value form", "[unit][transient_green]") {
  if (!__builtin_cpu_supports("avx")) return;  // the form is chosen only on processors with AVX
  const auto x = Samples();
  std::size_t differing = 0;
  for (std::size_t i = 0; i + 3 < x.size(); i += 4) {
    alignas(32) double out[4];
    hullopt::sk::PositiveLogarithmAvx4(&x[i], out);
    for (int m = 0; m < 4; ++m) {
      const double one = PositiveLogarithm(x[i + m]);
      if (std::memcmp(&out[m], &one, sizeof one) != 0) ++differing;
    }
  }
  CHECK(differing == 0);
}
#endif
