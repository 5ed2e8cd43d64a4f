// libFuzzer harness: the tank RAO CSV reader and the grouping by speed.
#include "fuzz_input.h"
#include "io/formats/input_error.h"
#include "io/formats/tank_rao_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace io = hullopt::io;
  const std::string path = hullopt::fuzz::WriteScratch(data, size, ".csv");
  try {
    const auto points = io::ReadTankRaoCsv(path);
    io::GroupTankRaoBySpeed(points, {0.75}, "fuzz", 0.0);
  } catch (const io::InputError&) {
  }
  return 0;
}
