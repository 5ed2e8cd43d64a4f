// Bad input to the time-domain strip solver gives clear errors (never a crash or a silent NaN).
#include <catch2/catch.hpp>
#include <stdexcept>
#include <string>

#include "seakeeping/sections/section_shapes.h"
#include "seakeeping/strip/strip_kernel_builder.h"
#include "seakeeping/strip/strip_marcher.h"
#include "seakeeping/strip/strip_operators.h"
#include "seakeeping/strip/td_heave_coefficients.h"

using namespace hullopt::sk;

TEST_CASE("options validation names the field and the rule", "[td][input]") {
  std::string err;
  StripOperatorOptions o;
  CHECK(o.IsValid(&err));
  o.field_points_per_panel = 0;
  CHECK_FALSE(o.IsValid(&err));
  CHECK(err.find("field_points_per_panel") != std::string::npos);
  TimeDomainSectionOptions t;
  CHECK(t.IsValid(&err));
  t.steps_per_period = 3;
  CHECK_FALSE(t.IsValid(&err));
  CHECK(err.find("steps_per_period") != std::string::npos);
}

TEST_CASE("bad panels, time steps and frequencies are refused", "[td][input]") {
  const auto good = PanelSymmetricSection(SemicircleContour(1.0), 6);
  auto above = good;
  above[2].z1 = 0.1;
  CHECK_THROWS_AS(BuildStripOperators({good, above}, 0.05, 1025, 9.81), std::invalid_argument);
  try {
    BuildStripOperators({good, above}, 0.05, 1025, 9.81);
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("step 1 panel 2") != std::string::npos);
  }
  CHECK_THROWS_AS(BuildStripOperators({good}, 0.0, 1025, 9.81), std::invalid_argument);
  CHECK_THROWS_AS(BuildFixedSectionOperators(good, 0, 0.05, 1025, 9.81), std::invalid_argument);
  CHECK_THROWS_AS(TimeDomainHeaveCoefficients(good, {}, 1025, 9.81), std::invalid_argument);
  CHECK_THROWS_AS(TimeDomainHeaveCoefficients(good, {-1.0}, 1025, 9.81), std::invalid_argument);
  const auto ops = BuildStripOperators({good, good, good, good}, 0.05, 1025, 9.81);  // >= 4 steps (cell faces)
  CHECK_THROWS_AS(BuildStripKernel(ops, {1.0, 2.0}), std::invalid_argument);
}

TEST_CASE("marcher refuses a wrong velocity size and steps past the end", "[td][input]") {
  const auto good = PanelSymmetricSection(SemicircleContour(1.0), 6);
  const auto ops = BuildFixedSectionOperators(good, 2, 0.05, 1025, 9.81);
  StripMarcher m(ops);
  CHECK_THROWS_AS(m.Advance(Eigen::VectorXd::Zero(5)), std::invalid_argument);
  m.Advance(Eigen::VectorXd::Ones(6));
  m.Advance(Eigen::VectorXd::Ones(6));
  CHECK_THROWS_AS(m.Advance(Eigen::VectorXd::Ones(6)), std::out_of_range);
}

TEST_CASE("steady-state-only operators refuse time marching from rest", "[td][input]") {
  const auto good = PanelSymmetricSection(SemicircleContour(1.0), 6);
  const auto ops = BuildFixedSectionOperators(good, 3, 0.05, 1025, 9.81, {}, /*steady_state_only=*/true);
  CHECK_NOTHROW(ops.LagMemory(2));
  StripMarcher m(ops);
  CHECK_THROWS_AS(m.Advance(Eigen::VectorXd::Ones(6)), std::logic_error);
}
