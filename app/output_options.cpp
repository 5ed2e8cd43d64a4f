#include "app/output_options.h"

#include <CLI/CLI.hpp>
#include <cstdarg>
#include <cstdio>
#include <iostream>

namespace hullopt::app {
namespace {

bool quiet_given = false;
bool no_plots_given = false;

}  // namespace

void AddQuietOption(CLI::App* command) {
  command->add_flag("--quiet", quiet_given,
                    "no result lines on stdout (warnings and errors still on stderr)");
}

void AddNoPlotsOption(CLI::App* command) {
  command->add_flag("--no-plots", no_plots_given,
                    "write the numbers only: no SVG figures and no report.html");
}

bool QuietGiven() { return quiet_given; }
bool NoPlotsGiven() { return no_plots_given; }

void ResetOutputOptions() {
  quiet_given = false;
  no_plots_given = false;
}

void Say(const char* format, ...) {
  if (quiet_given) return;
  va_list args;
  va_start(args, format);
  std::vprintf(format, args);
  va_end(args);
}

std::ostream& Out() {
  static std::ostream nowhere(nullptr);  // no buffer: every write is dropped
  return quiet_given ? nowhere : std::cout;
}

}  // namespace hullopt::app
