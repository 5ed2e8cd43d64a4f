#pragma once
// Shared by the libFuzzer harnesses: the readers take file paths, so each input is written to a per-process
// scratch file first. Only io::InputError is an accepted outcome; any other exception escapes and libFuzzer
// reports it as a crash (that is the bug class: an internal error instead of a one-line input error).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace hullopt::fuzz {

inline std::string WriteScratch(const uint8_t* data, size_t size, const char* extension) {
  const std::string path = "/tmp/hullopt-fuzz-" + std::to_string(::getpid()) + extension;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) __builtin_trap();
  if (size > 0 && std::fwrite(data, 1, size, f) != size) __builtin_trap();
  std::fclose(f);
  return path;
}

}  // namespace hullopt::fuzz
