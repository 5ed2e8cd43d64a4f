// Non-finite numbers never reach an output: the RAO check names the motion and frequency, the JSON guard names
// the quantity's path and the design; a resonance above the stated limit is a warning with its value.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "io/finite_json.h"
#include "io/input_error.h"
#include "seakeeping/motions/rao_checks.h"

using namespace hullopt;

namespace {
sk::RaoTable Table(double heave_peak) {
  sk::RaoTable t;
  for (double w : {0.5, 1.0, 1.5}) {
    t.omega_rad_s.push_back(w);
    t.omega_e_rad_s.push_back(w);
    t.heave.push_back(w == 1.0 ? heave_peak : 1.0);
    t.pitch.push_back(1.0);
  }
  return t;
}
}  // namespace

TEST_CASE("a non-finite RAO is refused naming motion and frequency", "[finite]") {
  sk::RaoTable t = Table(1.0);
  CHECK_NOTHROW(sk::RequireFiniteRaos(t));
  t.pitch[2] = {std::numeric_limits<double>::infinity(), 0.0};
  CHECK_THROWS_WITH(sk::RequireFiniteRaos(t), Catch::Contains("pitch RAO at omega = 1.5 rad/s"));
}

TEST_CASE("a resonance above the limit is a warning with its peak", "[finite]") {
  CHECK(sk::RaoResonanceWarnings(Table(0.99 * sk::kResonanceWarningRao)).empty());
  const auto w = sk::RaoResonanceWarnings(Table(12.0));
  REQUIRE(w.size() == 1);
  CHECK_THAT(w[0], Catch::Contains("heave RAO peaks at 12 m/m at omega = 1 rad/s"));
}

TEST_CASE("the JSON guard names the path and the design of a non-finite number", "[finite]") {
  nlohmann::json j;
  j["designs"] = nlohmann::json::array();
  j["designs"].push_back({{"name", "a"}, {"msi_pct", 3.0}});
  j["designs"].push_back({{"name", "b"}, {"msi_pct", std::nan("")}});
  CHECK_THROWS_WITH(io::RequireFiniteJson(j, "summary.json"),
                    Catch::Contains("summary.json: quantity designs[1].msi_pct = nan (design 'b')"));
  j["designs"][1]["msi_pct"] = 1.0;
  CHECK_NOTHROW(io::RequireFiniteJson(j, "summary.json"));
}
