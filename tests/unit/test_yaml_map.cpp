// Strict YAML reading: unknown keys, wrong types, non-finite values and missing keys are refused with the
// file, line, key and rule in the message.
#include <catch2/catch.hpp>

#include "io/yaml_map.h"

using hullopt::io::InputError;
using hullopt::io::YamlMap;

namespace {
YamlMap FromText(const std::string& text) {
  return YamlMap(YAML::Load(text), "", "test.yaml", YAML::Node(YAML::NodeType::Map));
}
}  // namespace

TEST_CASE("reads values and fills defaults into the resolved tree", "[yaml]") {
  auto m = FromText("a: 1.5\nb: [1, 2]\nsub: {c: x}\n");
  CHECK(m.Number("a") == 1.5);
  CHECK(m.Number("d", 7.0) == 7.0);
  CHECK(m.Numbers("b").size() == 2);
  auto sub = m.Map("sub");
  CHECK(sub.String("c") == "x");
  sub.Finish();
  m.Finish();
  CHECK(m.resolved()["d"].as<double>() == 7.0);
  CHECK(m.resolved()["sub"]["c"].as<std::string>() == "x");
}

TEST_CASE("unknown key is named with its line", "[yaml][bad-input]") {
  auto m = FromText("a: 1\nCbb: 2\n");
  m.Number("a");
  CHECK_THROWS_WITH(m.Finish(), Catch::Contains("test.yaml:2") && Catch::Contains("unknown key 'Cbb'"));
}

TEST_CASE("wrong type, NaN, missing key and empty list are refused", "[yaml][bad-input]") {
  auto m = FromText("a: hello\nn: .nan\nl: []\ni: 1.5\n");
  CHECK_THROWS_WITH(m.Number("a"), Catch::Contains("key 'a'") && Catch::Contains("must be a number"));
  CHECK_THROWS_WITH(m.Number("n"), Catch::Contains("finite"));
  CHECK_THROWS_WITH(m.Number("missing"), Catch::Contains("missing required key 'missing'"));
  CHECK_THROWS_WITH(m.Numbers("l"), Catch::Contains("empty"));
  CHECK_THROWS_WITH(m.Integer("i"), Catch::Contains("whole number"));
  CHECK_THROWS_WITH(m.Choice("a", {"x", "y"}), Catch::Contains("one of: x, y"));
}

TEST_CASE("missing file and syntax errors name the file", "[yaml][bad-input]") {
  CHECK_THROWS_AS(YamlMap::LoadFile("/nonexistent/x.yaml"), InputError);
}
