// libFuzzer harness: the offsets CSV reader, then the hydrostatics and plausibility checks of what it read.
#include "fuzz_input.h"
#include "evaluation/hull_plausibility.h"
#include "io/formats/input_error.h"
#include "io/formats/offsets_csv.h"
#include "parametric_hull/hydrostatics.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace io = hullopt::io;
  namespace eval = hullopt::eval;
  const std::string path = hullopt::fuzz::WriteScratch(data, size, ".csv");
  try {
    hullopt::hull::HullForm h;
    h.type = "offsets";
    h.draught_m = 0.15;
    h.bodies = {io::ReadOffsetsCsv(path, h.draught_m)};
    eval::CheckHull(h, path);
  } catch (const io::InputError&) {
  }
  return 0;
}
