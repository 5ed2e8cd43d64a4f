// eval::CheckHeadingList (evaluation/oblique_design.h): the one rule of a list of wave headings, used by the
// campaign objective over headings (MsiObjectiveOptions::IsValid) and the operability polar (PolarOptions::
// IsValid); the messages are the ones docs/bad-inputs.md lists for both.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "evaluation/oblique_design.h"

using hullopt::eval::CheckHeadingList;

TEST_CASE("a heading list: each within [0, 360), none twice") {
  CHECK(CheckHeadingList({}, "headings_deg").empty());
  CHECK(CheckHeadingList({0.0, 90.0, 180.0, 359.5}, "headings_deg").empty());
  CHECK(CheckHeadingList({180.0, 360.0}, "headings_deg") == "headings_deg[1] = 360: must be within [0, 360)");
  CHECK(CheckHeadingList({-1.0}, "headings_deg") == "headings_deg[0] = -1: must be within [0, 360)");
  CHECK(CheckHeadingList({std::numeric_limits<double>::quiet_NaN()}, "h") == "h[0] = nan: must be within [0, 360)");
  CHECK(CheckHeadingList({180.0, 150.0, 180.0}, "headings_deg") == "headings_deg[2] = 180: given twice");
  // The first fault in list order: entry 1 given twice comes before entry 2 out of range.
  CHECK(CheckHeadingList({90.0, 90.0, 400.0}, "headings_deg") == "headings_deg[1] = 90: given twice");
}
