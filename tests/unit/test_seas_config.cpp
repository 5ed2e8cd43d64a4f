// Reading seas, MSI options and passenger points from YAML: the list and sea-state-line forms, defaults in
// the resolved tree, and one-line errors naming file, line, key, value and rule.
#include <catch2/catch.hpp>
#include <string>

#include "io/config/seas_config.h"

using hullopt::io::InputError;
using hullopt::io::YamlMap;
namespace io = hullopt::io;
namespace sk = hullopt::sk;

namespace {
YamlMap FromText(const std::string& text) {
  return YamlMap(YAML::Load(text), "", "test.yaml", YAML::Node(YAML::NodeType::Map));
}
std::string ErrorOf(const std::string& text) {
  try {
    auto m = FromText(text);
    io::ReadSeas(m);
    io::ReadMsiOptions(m);
    auto pos = m.MapOrEmpty("positions");
    const sk::HullExtent hull{20.0, 30.0};
    io::ReadPassengerPoints(pos, &hull);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST_CASE("seas list: JONSWAP with Tz or Tp, Bretschneider, defaults", "[config]") {
  auto m = FromText(
      "seas:\n"
      "  - { spectrum: jonswap, Hs_m: 3.0, Tz_s: 7.5, gamma: 3.3 }\n"
      "  - { Hs_m: 1.0, Tp_s: 7.0 }\n"
      "  - { spectrum: bretschneider, Hs_m: 2.0, Tz_s: 6.5 }\n");
  const auto seas = io::ReadSeas(m);
  REQUIRE(seas.size() == 3);
  CHECK(seas[0].Hs_m == 3.0);
  CHECK(seas[0].Tz_s == 7.5);
  CHECK(seas[1].Tp_s == 7.0);
  CHECK(std::isnan(seas[1].Tz_s));
  CHECK(seas[1].gamma == 3.3);  // default
  CHECK(seas[2].spectrum == sk::SpectrumType::kBretschneider);
  CHECK(seas[2].gamma == 1.0);
  CHECK(m.resolved()["seas"][1]["gamma"].as<double>() == 3.3);
  CHECK(m.resolved()["seas"][1]["spectrum"].as<std::string>() == "jonswap");
}

TEST_CASE("sea_state_line expands to the paper's Tz(Hs)", "[config]") {
  auto m = FromText("seas:\n  - sea_state_line: { Hs_m: [0.5, 1.0, 3.0] }\n  - { Hs_m: 4, Tz_s: 9 }\n");
  const auto seas = io::ReadSeas(m);
  REQUIRE(seas.size() == 4);
  CHECK(seas[0].Tz_s == Approx(5.0));
  CHECK(seas[1].Tz_s == Approx(5.5));
  CHECK(seas[2].Tz_s == Approx(7.5));
  CHECK(seas[3].Tz_s == 9.0);
}

TEST_CASE("MSI options and passenger points", "[config]") {
  auto m = FromText(
      "msi: { model: iso_2631, exposure_h: 4, acceleration: rms }\n"
      "positions: { points: [ { name: bridge, x_from_cg_m: 12.5 }, { name: aft_saloon, x_from_cg_m: -15 } ] "
      "}\n");
  const auto o = io::ReadMsiOptions(m);
  CHECK(o.model == sk::MsiModel::kIso2631Msdv);
  CHECK(o.exposure_h == 4.0);
  CHECK(o.statistic == sk::AccelerationStatistic::kRms);
  CHECK(o.frequency == sk::MsiFrequency::kDisplacementM4M2);
  auto pos = m.Map("positions");
  const sk::HullExtent hull{20.0, 30.0};
  const auto points = io::ReadPassengerPoints(pos, &hull);
  REQUIRE(points.size() == 2);
  CHECK(points[1].name == "aft_saloon");
  CHECK(points[1].x_from_cg_m == -15.0);
  auto defaults = FromText("{}");
  CHECK(io::ReadMsiOptions(defaults).model == sk::MsiModel::kLloyd);
  CHECK(defaults.resolved()["msi"]["exposure_h"].as<double>() == 2.0);
}

TEST_CASE("bad seas, MSI options and points give one clear error", "[config][bad-input]") {
  auto has = [](const std::string& text, const std::string& part) {
    const std::string e = ErrorOf(text);
    INFO(e);
    return e.find(part) != std::string::npos && e.find('\n') == std::string::npos;
  };
  CHECK(has("seas:\n  - { Hs_m: 0, Tz_s: 7.5 }\n",
            "test.yaml:2: key 'seas[0].Hs_m': Hs_m = 0: significant wave height must be > 0"));
  CHECK(has("seas:\n  - { Hs_m: -2, Tz_s: 7.5 }\n", "Hs_m = -2"));
  CHECK(has("seas:\n  - { Hs_m: 1, Tz_s: 1.9 }\n",
            "key 'seas[0].Tz_s': Tz_s = 1.9: zero-crossing period must be "
            "within 2..25 s"));
  CHECK(has("seas:\n  - { Hs_m: 1, Tz_s: 25.5 }\n", "Tz_s = 25.5"));
  CHECK(has("seas:\n  - { Hs_m: 1, Tz_s: 6, gamma: 0.8 }\n", "key 'seas[0].gamma': gamma = 0.8"));
  CHECK(has("seas:\n  - { Hs_m: 1, Tp_s: 1.0 }\n", "implies Tz"));
  CHECK(has("seas:\n  - { Hs_m: 1 }\n", "key 'seas[0]': give exactly one of Tz_s and Tp_s"));
  CHECK(has("seas: []\n", "must not be an empty list"));
  CHECK(has("other: 1\n", "missing required key 'seas'"));
  CHECK(has("seas:\n  - { spectrum: pm, Hs_m: 1, Tz_s: 6 }\n", "must be one of: jonswap, bretschneider"));
  CHECK(has("seas:\n  - sea_state_line: { Hs_m: [1, 0] }\n", "element 2: Hs_m = 0"));
  CHECK(has("seas:\n  - sea_state_line: { Hs_m: [1], gamma: 0.5 }\n", "sea_state_line.gamma': element 1"));
  CHECK(has("seas:\n  - sea_state_line: { Hs_m: [1] }\n    Hs_m: 2\n", "unknown key"));
  CHECK(has("seas: [ { Hs_m: 1, Tz_s: 6 } ]\nmsi: { exposure_h: 3 }\n", "2-hour exposure only"));
  CHECK(has("seas: [ { Hs_m: 1, Tz_s: 6 } ]\nmsi: { model: magic }\n", "must be one of: lloyd"));
  CHECK(has(
      "seas: [ { Hs_m: 1, Tz_s: 6 } ]\npositions: { points: [ { name: a, x_from_cg_m: 31 } ] }\n",
      "key 'positions.points[0].x_from_cg_m': passenger position 'a': x_from_cg_m = 31 is outside the hull"));
  CHECK(has("seas: [ { Hs_m: 1, Tz_s: 6 } ]\npositions: { points: [ { name: a, x_from_cg_m: -21 } ] }\n",
            "outside the hull, which spans -20 (transom) to 30 (bow)"));
  CHECK(has("seas: [ { Hs_m: 1, Tz_s: 6 } ]\npositions: { points: [ { name: lcg, x_from_cg_m: 0 } ] }\n",
            "reserved"));
  CHECK(
      has("seas: [ { Hs_m: 1, Tz_s: 6 } ]\n"
          "positions: { points: [ { name: a, x_from_cg_m: 0 }, { name: a, x_from_cg_m: 1 } ] }\n",
          "unique"));
}
