// Paths in a config: relative to the folder of the config that names them, never to the working folder;
// absolute as written; recorded absolute in the resolved tree; a missing file named with key, text and path.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "io/config/config_path.h"

namespace fs = std::filesystem;
using hullopt::io::ConfigFilePath;
using hullopt::io::ConfigFilePaths;
using hullopt::io::InputError;
using hullopt::io::ResolveConfigPath;
using hullopt::io::YamlMap;

namespace {
const fs::path kDir = fs::path(HULLOPT_BINARY_DIR) / "config_path_test";

void Touch(const fs::path& p) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << "\n";
}

YamlMap FromText(const std::string& text, const fs::path& config) {
  return YamlMap(YAML::Load(text), "", config.string(), YAML::Node(YAML::NodeType::Map));
}
}  // namespace

TEST_CASE("a relative path is relative to the config's folder", "[config-path]") {
  const std::string config = (kDir / "cases" / "a.yaml").string();
  CHECK(ResolveConfigPath("data/x.csv", config) == (kDir / "cases" / "data" / "x.csv").string());
  CHECK(ResolveConfigPath("../data/x.csv", config) == (kDir / "data" / "x.csv").string());
  CHECK(ResolveConfigPath("/abs/x.csv", config) == "/abs/x.csv");
  CHECK(ResolveConfigPath("/abs/./y/../x.csv", config) == "/abs/x.csv");
  // A config named relative to the working folder: its folder, made absolute.
  CHECK(ResolveConfigPath("x.csv", "sub/a.yaml") == (fs::current_path() / "sub" / "x.csv").string());
  CHECK(ResolveConfigPath("x.csv", "a.yaml") == (fs::current_path() / "x.csv").string());
}

TEST_CASE("the working folder plays no part", "[config-path][bad-input]") {
  // A file that exists relative to the working folder but not beside the config is refused, with the key,
  // the text written and the path it resolved to.
  const fs::path before = fs::current_path(), cwd = kDir / "cwd";
  Touch(cwd / "config_path_test_cwd_only.csv");
  fs::current_path(cwd);
  auto m = FromText("file: config_path_test_cwd_only.csv\n", kDir / "b.yaml");
  try {
    ConfigFilePath(m, "file");
    FAIL("a path relative to the working folder was accepted");
  } catch (const InputError& e) {
    const std::string msg = e.what();
    CHECK_THAT(msg, Catch::Contains("key 'file' = config_path_test_cwd_only.csv: no such file " +
                                    (kDir / "config_path_test_cwd_only.csv").string()));
    CHECK_THAT(msg, Catch::Contains("relative to the config's folder, " + kDir.string()));
  }
  fs::current_path(before);
}

TEST_CASE("a resolved path is recorded absolute", "[config-path]") {
  Touch(kDir / "data" / "x.csv");
  Touch(kDir / "data" / "y.csv");
  auto m = FromText("file: data/x.csv\nfiles: [data/x.csv, ../config_path_test/data/y.csv]\n", kDir / "c.yaml");
  CHECK(ConfigFilePath(m, "file") == (kDir / "data" / "x.csv").string());
  CHECK(m.resolved()["file"].as<std::string>() == (kDir / "data" / "x.csv").string());
  const auto files = ConfigFilePaths(m, "files");
  REQUIRE(files.size() == 2);
  CHECK(files[1] == (kDir / "data" / "y.csv").string());
  CHECK(m.resolved()["files"][1].as<std::string>() == (kDir / "data" / "y.csv").string());
  m.Finish();
  // Read again from the resolved tree (as config.resolved.yaml is), in another folder: the same files.
  auto again = FromText(YAML::Dump(m.resolved()), fs::temp_directory_path() / "elsewhere.yaml");
  CHECK(ConfigFilePath(again, "file") == files[0]);
  CHECK(ConfigFilePaths(again, "files") == files);
}
