// Frequencies of measured points against the deep-water dispersion relation and the head-sea encounter
// definition written out here.
#include <catch2/catch.hpp>
#include <cmath>

#include "optimizer/tank_rao_frequency.h"

using namespace hullopt::opt;

namespace {
constexpr double kRoundOff = 1e-12;  // a few floating-point operations on O(1–10) numbers
constexpr double kG = 9.81;
}  // namespace

TEST_CASE("lambda/L and omega_e give the wave and encounter frequencies", "[frequency]") {
  // ω = 2 rad/s: λ = 2πg/ω²; a ship of that length at Fn 0.5 has U = 0.5 sqrt(gL); ω_e = ω + ω²U/g.
  const double omega = 2.0, L = 2 * M_PI * kG / (omega * omega);
  const double U = 0.5 * std::sqrt(kG * L), omega_e = omega + omega * omega * U / kG;
  TankRaoPoint p;
  p.Fn = 0.5;
  p.has_lambda_over_L = true;
  p.lambda_over_L = 1.0;
  CHECK(PointWaveFrequency(p, L, kG) == Approx(omega).epsilon(kRoundOff));
  CHECK(PointEncounterFrequency(p, L, kG) == Approx(omega_e).epsilon(kRoundOff));
  TankRaoPoint q;
  q.Fn = 0.5;
  q.has_omega_e = true;
  q.omega_e_rad_s = omega_e;
  CHECK(PointWaveFrequency(q, L, kG) == Approx(omega).epsilon(kRoundOff));
  CHECK(PointEncounterFrequency(q, L, kG) == omega_e);
}

TEST_CASE("case grid: increasing, duplicates merged, every point mapped", "[frequency]") {
  CalibrationCase c;
  for (double lr : {1.0, 2.0, 1.5, 2.0}) {
    TankRaoPoint p;
    p.Fn = 0.75;
    p.has_lambda_over_L = true;
    p.lambda_over_L = lr;
    c.points.push_back(p);
  }
  const auto g = WaveFrequencyGrid(c, 3.0, kG);
  REQUIRE(g.omega_rad_s.size() == 3);
  CHECK(g.omega_rad_s[0] < g.omega_rad_s[1]);
  CHECK(g.omega_rad_s[1] < g.omega_rad_s[2]);
  REQUIRE(g.index_of_point.size() == 4);
  CHECK(g.index_of_point[0] == 2);  // the shortest wave has the highest frequency
  CHECK(g.index_of_point[1] == 0);
  CHECK(g.index_of_point[2] == 1);
  CHECK(g.index_of_point[3] == 0);
  for (std::size_t i = 0; i < 4; ++i)
    CHECK(g.omega_rad_s[g.index_of_point[i]] == PointWaveFrequency(c.points[i], 3.0, kG));
}
