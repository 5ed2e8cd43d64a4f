// Resolution check: the comparison of a coarse and a fine result of one design against hand-made tables
// whose peak and MSI changes are known by construction.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "seas/resolution_check.h"

using namespace hullopt::sk;

namespace {

RaoTable Table(double heave_peak, double pitch_peak) {
  RaoTable t;
  t.omega_rad_s = {0.5, 1.0, 1.5};
  t.omega_e_rad_s = {0.8, 2.0, 3.5};
  t.heave = {{0.9, 0.0}, {0.0, heave_peak}, {0.3, 0.0}};
  t.pitch = {{0.5, 0.0}, {pitch_peak, 0.0}, {0.0, -0.2}};
  return t;
}

DesignEvaluation Evaluation(std::vector<double> mean_msi) {
  DesignEvaluation e;
  for (double m : mean_msi) {
    SeaEvaluation s;
    s.mean.msi_pct = m;
    e.seas.push_back(s);
  }
  return e;
}

}  // namespace

TEST_CASE("a result that moves less than the tolerances is converged, with no warning", "[resolution]") {
  const auto r = CompareResolutions(Table(2.0, 1.2), Table(2.04, 1.19), Evaluation({10.0, 40.0}),
                                    Evaluation({10.3, 40.9}), 40, 14, 80, 28);
  CHECK(r.converged);
  CHECK(r.warning.empty());
  CHECK(r.heave_peak == 2.0);
  CHECK(r.heave_peak_fine == 2.04);
  CHECK(r.heave_peak_change == Approx(0.02).epsilon(1e-12));
  CHECK(r.pitch_peak_change == Approx(-1.0 / 120.0).epsilon(1e-12));
  CHECK(r.max_msi_change_pct == Approx(0.9).epsilon(1e-12));
  CHECK(r.max_msi_change_sea == 1);
}

TEST_CASE("an MSI change above one point flags the design and names the numbers", "[resolution]") {
  const auto r = CompareResolutions(Table(2.0, 1.2), Table(2.0, 1.2), Evaluation({10.0, 40.0}),
                                    Evaluation({11.5, 40.0}), 40, 14, 80, 28);
  CHECK_FALSE(r.converged);
  CHECK(r.max_msi_change_sea == 0);
  CHECK(r.warning.find("40 sections x 14 panels") != std::string::npos);
  CHECK(r.warning.find("1.50 points") != std::string::npos);
}

TEST_CASE("a heave peak that grows by more than 3% flags the design", "[resolution]") {
  const auto r = CompareResolutions(Table(2.0, 1.2), Table(2.1, 1.2), Evaluation({10.0}), Evaluation({10.0}), 40,
                                    14, 80, 28);
  CHECK_FALSE(r.converged);
  CHECK(r.warning.find("+5.0%") != std::string::npos);
}

TEST_CASE("a non-finite fine result is never counted as converged", "[resolution]") {
  const auto r = CompareResolutions(Table(2.0, 1.2), Table(2.0, 1.2), Evaluation({10.0}), Evaluation({NAN}), 40,
                                    14, 80, 28);
  CHECK_FALSE(r.converged);
}

TEST_CASE("mismatched grids, sea lists and options are refused", "[resolution]") {
  RaoTable other = Table(2.0, 1.2);
  other.omega_rad_s[1] = 1.1;
  CHECK_THROWS_AS(CompareResolutions(Table(2, 1), other, Evaluation({1}), Evaluation({1}), 40, 14, 80, 28),
                  std::invalid_argument);
  CHECK_THROWS_AS(CompareResolutions(Table(2, 1), Table(2, 1), Evaluation({1}), Evaluation({1, 2}), 40, 14, 80, 28),
                  std::invalid_argument);
  ResolutionCheckOptions bad;
  bad.msi_tolerance_pct = 0.0;
  CHECK_THROWS_AS(
      CompareResolutions(Table(2, 1), Table(2, 1), Evaluation({1}), Evaluation({1}), 40, 14, 80, 28, bad),
      std::invalid_argument);
}
