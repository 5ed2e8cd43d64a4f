// Strict YAML reading: unknown keys, wrong types, non-finite values and missing keys are refused with the
// file, line, key and rule in the message.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>

#include "io/config/yaml_map.h"

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

TEST_CASE("duplicate keys, second documents and non-text keys are refused with their line", "[yaml][bad-input]") {
  const std::string file = "test_strict.yaml";
  auto load = [&](const std::string& text) {
    std::ofstream(file) << text;
    return YamlMap::LoadFile(file);
  };
  CHECK_THROWS_WITH(load("a: 1\nb: {c: 1, c: 2}\n"), Catch::Contains(":2: duplicate key 'c'"));
  CHECK_THROWS_WITH(load("a: 1\n---\nb: 2\n"), Catch::Contains(":3: a second YAML document"));
  CHECK_THROWS_WITH(load("a: 1\n? [x]\n: 2\n"), Catch::Contains(":2: a key must be plain text"));
  CHECK_THROWS_WITH(load("v: {!L: [8, 16]}\n"), Catch::Contains(":1: a key must be plain text"));
  CHECK_THROWS_WITH(load("- 1\n- 2\n"), Catch::Contains("must be a mapping"));
  CHECK_NOTHROW(load("---\na: 1\nb: {c: 1, d: 2}\n"));  // a leading document marker is one document
  // A ',' where a document's node begins makes yaml-cpp's LoadAll loop forever; each is refused at its line.
  CHECK_THROWS_WITH(load(",\na: 1\n"), Catch::Contains(":1: YAML syntax error: a ','"));
  CHECK_THROWS_WITH(load("  a: 1\n,\n"), Catch::Contains(":2: YAML syntax error: a ','"));
  CHECK_THROWS_WITH(load("  a: |\n    x\n, y\n"), Catch::Contains(":3: YAML syntax error: a ','"));
  CHECK_THROWS_WITH(load("    a: 1\n  b: 2\n"), Catch::Contains(":2: this line is indented less"));
  CHECK_NOTHROW(load("  a: [1\n, 2]\n  b: \"x\n, y\"\n"));  // a ',' inside a list or a quoted text is data
  std::remove(file.c_str());
}

TEST_CASE("ranged whole numbers state their range", "[yaml][bad-input]") {
  auto m = FromText("n: 1e12\nf: 2.5\nok: 7\n");
  CHECK_THROWS_WITH(m.Integer("n", 1, 1, 1000000), Catch::Contains("n' = 1e12: must lie in [1, 1000000]"));
  CHECK_THROWS_WITH(m.Integer("f", 1, 1, 10), Catch::Contains("must be a whole number"));
  CHECK(m.Integer("ok", 1, 1, 10) == 7);
  CHECK(m.Integer("absent", 3, 1, 10) == 3);
}
