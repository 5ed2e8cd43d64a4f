// Sampling for design-space exploration: the Sobol generator against the published first points of the
// Joe–Kuo sequence and the (0, m, 1)-net property in every dimension; Latin hypercube stratification and
// seeded reproducibility.
#include <catch2/catch.hpp>
#include <set>

#include "optimizer/design_sampling.h"
#include "optimizer/sobol_sequence.h"

using hullopt::opt::SobolSequence;

TEST_CASE("Sobol points 0..7 in dimensions 1-3 equal the published sequence", "[sampling][sobol]") {
  // Joe & Kuo (2008) sequence in Gray-code order, as tabulated e.g. by scipy.stats.qmc.Sobol(scramble=False)
  // and derived by hand from m = (1), (1, 3): dyadic rationals, exact in binary.
  const double expected[8][3] = {{0, 0, 0},
                                 {0.5, 0.5, 0.5},
                                 {0.75, 0.25, 0.25},
                                 {0.25, 0.75, 0.75},
                                 {0.375, 0.375, 0.625},
                                 {0.875, 0.875, 0.125},
                                 {0.625, 0.125, 0.875},
                                 {0.125, 0.625, 0.375}};
  SobolSequence s(3);
  for (int i = 0; i < 8; ++i) {
    const auto p = s.Point(i);
    for (int d = 0; d < 3; ++d) CHECK(p[d] == expected[i][d]);
  }
}

TEST_CASE("every Sobol dimension is a (0, m, 1)-net: one point per dyadic interval", "[sampling][sobol]") {
  constexpr int kM = 10;  // first 2^10 points (index 0 included)
  SobolSequence s(SobolSequence::kMaxDimension);
  for (int d = 0; d < SobolSequence::kMaxDimension; ++d) {
    std::set<long> cells;
    for (int i = 0; i < (1 << kM); ++i) cells.insert(static_cast<long>(s.Point(i)[d] * (1 << kM)));
    CHECK(cells.size() == (1u << kM));
  }
}

TEST_CASE("Sobol dimensions 1 and 2 form a (0, m, 2)-net", "[sampling][sobol]") {
  // Every elementary box of area 2^-m (2^a by 2^(m-a) cells) holds exactly one of the first 2^m points.
  constexpr int kM = 8;
  SobolSequence s(2);
  for (int a = 0; a <= kM; ++a) {
    std::set<std::pair<long, long>> cells;
    for (int i = 0; i < (1 << kM); ++i) {
      const auto p = s.Point(i);
      cells.insert({static_cast<long>(p[0] * (1 << a)), static_cast<long>(p[1] * (1 << (kM - a)))});
    }
    CHECK(cells.size() == (1u << kM));
  }
}

TEST_CASE("dimension limits are refused", "[sampling][sobol][bad-input]") {
  CHECK_THROWS_AS(SobolSequence(0), std::invalid_argument);
  CHECK_THROWS_AS(SobolSequence(17), std::invalid_argument);
}

TEST_CASE("Latin hypercube: one point per stratum, reproducible from the seed", "[sampling][lhs]") {
  constexpr int kN = 50, kD = 4;
  const auto a = hullopt::opt::LatinHypercube(kN, kD, 7);
  const auto b = hullopt::opt::LatinHypercube(kN, kD, 7);
  const auto c = hullopt::opt::LatinHypercube(kN, kD, 8);
  CHECK(a == b);
  CHECK(a != c);
  for (int d = 0; d < kD; ++d) {
    std::set<int> strata;
    for (const auto& p : a) {
      REQUIRE(p[d] >= 0.0);
      REQUIRE(p[d] < 1.0);
      strata.insert(static_cast<int>(p[d] * kN));
    }
    CHECK(strata.size() == static_cast<std::size_t>(kN));
  }
}

TEST_CASE("samples are scaled to the variable bounds", "[sampling]") {
  hullopt::opt::CampaignDefinition c;
  c.variables = {{"a", 8, 16, 10}, {"b", -1, 1, 0}};
  for (const char* method : {"sobol", "lhs"}) {
    const auto xs = hullopt::opt::SampleDesigns(c, method, 64);
    REQUIRE(xs.size() == 64);
    for (const auto& x : xs) {
      CHECK(x[0] >= 8);
      CHECK(x[0] < 16);
      CHECK(x[1] >= -1);
      CHECK(x[1] < 1);
    }
  }
  CHECK(hullopt::opt::SampleDesigns(c, "sobol", 1)[0] ==
        std::vector<double>{12, 0});  // Sobol point 1: centre
}
