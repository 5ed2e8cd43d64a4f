// libFuzzer harness: the STL reader (ASCII and binary) and the slicer.
#include "fuzz_input.h"
#include "io/formats/input_error.h"
#include "io/formats/stl_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace io = hullopt::io;
  const std::string path = hullopt::fuzz::WriteScratch(data, size, ".stl");
  try {
    const io::StlMesh mesh = io::ReadStl(path);
    io::SliceStl(mesh, 11, 0.5, path);
  } catch (const io::InputError&) {
  }
  return 0;
}
