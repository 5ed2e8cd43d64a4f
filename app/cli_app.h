#pragma once
// CLI11's App, declared only: the headers of app/ name it, and only the files that add options or parse the
// command line include <CLI/CLI.hpp> (the largest header of the build, several seconds per file).
namespace CLI {
class App;
}  // namespace CLI
