// libFuzzer harness: reading a rao.csv back into a RAO table.
#include "fuzz_input.h"
#include "io/formats/input_error.h"
#include "io/formats/rao_table_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace io = hullopt::io;
  const std::string path = hullopt::fuzz::WriteScratch(data, size, ".csv");
  try {
    io::ReadRaoTableCsv(path);
  } catch (const io::InputError&) {
  }
  return 0;
}
