// Non-finite numbers never reach an output: the RAO check names the motion and frequency, the JSON guard names
// the quantity's path and the design; a resonance above the stated limit is a warning with its value.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "io/formats/finite_json.h"
#include "io/formats/input_error.h"
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
  // Table's three samples are also an under-sampled peak (its own warning, tested below): count only the
  // resonance warnings here.
  auto resonance = [](const std::vector<std::string>& all) {
    std::vector<std::string> out;
    for (const auto& w : all)
      if (w.find("lightly damped resonance") != std::string::npos) out.push_back(w);
    return out;
  };
  CHECK(resonance(sk::RaoResonanceWarnings(Table(0.99 * sk::kResonanceWarningRao))).empty());
  const auto w = resonance(sk::RaoResonanceWarnings(Table(12.0)));
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

TEST_CASE("an RAO peak narrower than the frequency grid is a warning; a resolved one is not", "[finite]") {
  // One degree of freedom, X = 1/(1 − ω² + i b ω), b = 0.02: peak 1/b = 50 at ω = 1, half-power half-width
  // b/2 = 0.01 rad/s (closed form). Sampled every 0.037 rad/s with no sample within 0.01 of the peak, the
  // largest sample is far below 50 and the fitted resonance says so; sampled every 0.002 rad/s (ten points
  // per half-width) the largest sample is within the tolerance of the peak and no warning is given.
  auto table = [](double from, double step, int n) {
    sk::RaoTable t;
    for (int i = 0; i < n; ++i) {
      const double w = from + step * i;
      t.omega_rad_s.push_back(w);
      t.omega_e_rad_s.push_back(w);
      t.heave.push_back(1.0 / std::complex<double>(1 - w * w, 0.02 * w));
      t.pitch.push_back(1.0);
    }
    return t;
  };
  const auto coarse = sk::RaoResonanceWarnings(table(0.5, 0.037, 28));  // samples at ..., 0.981, 1.018, ...
  bool sampled = false;
  for (const auto& w : coarse) sampled = sampled || w.find("heave RAO peak is under-sampled") != std::string::npos;
  CHECK(sampled);
  for (const auto& w : sk::RaoResonanceWarnings(table(0.9, 0.002, 101)))
    CHECK(w.find("under-sampled") == std::string::npos);
}
