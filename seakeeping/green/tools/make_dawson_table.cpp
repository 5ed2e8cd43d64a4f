// Build tool: writes the Dawson-integral table (seakeeping/green/dawson_integral_table.h) to the file named by
// its argument, as the doubles of ComputeDawsonIntegralTable() in this machine's byte order, which
// dawson_integral_table_data.c embeds into the library. Not part of the library (seakeeping/CMakeLists.txt).
#include <cstdio>
#include <string>

#include "seakeeping/green/dawson_integral_table.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT_FILE\n", argv[0]);
    return 2;
  }
  const auto table = hullopt::sk::dawson_table::ComputeDawsonIntegralTable();
  // Written whole or not at all: to a temporary file renamed over the output.
  const std::string path = argv[1], temporary = path + ".tmp";
  std::FILE* f = std::fopen(temporary.c_str(), "wb");
  if (f == nullptr) {
    std::perror(temporary.c_str());
    return 1;
  }
  const bool written = std::fwrite(table.data(), sizeof(table[0]), table.size(), f) == table.size();
  if (std::fclose(f) != 0 || !written || std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::perror(path.c_str());
    std::remove(temporary.c_str());
    return 1;
  }
  return 0;
}
