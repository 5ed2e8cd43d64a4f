#include "io/formats/utf8_text.h"

#include <cstdio>

#include "io/formats/input_error.h"

namespace hullopt::io {

bool IsValidUtf8(const std::string& text, std::size_t* bad_offset) {
  const auto* s = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t n = text.size();
  std::size_t i = 0;
  auto bad = [&] {
    if (bad_offset) *bad_offset = i;
    return false;
  };
  while (i < n) {
    const unsigned char c = s[i];
    std::size_t len = 0;
    unsigned lo = 0x80, hi = 0xBF;  // allowed range of the second byte (RFC 3629 table)
    if (c < 0x80) {
      ++i;
      continue;
    } else if (c >= 0xC2 && c <= 0xDF) {
      len = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
      len = 3;
      if (c == 0xE0) lo = 0xA0;  // overlong
      if (c == 0xED) hi = 0x9F;  // surrogates
    } else if (c >= 0xF0 && c <= 0xF4) {
      len = 4;
      if (c == 0xF0) lo = 0x90;  // overlong
      if (c == 0xF4) hi = 0x8F;  // above U+10FFFF
    } else {
      return bad();
    }
    if (i + len > n || s[i + 1] < lo || s[i + 1] > hi) return bad();
    for (std::size_t k = 2; k < len; ++k)
      if (s[i + k] < 0x80 || s[i + k] > 0xBF) return bad();
    i += len;
  }
  return true;
}

void RequireUtf8(const std::string& text, const std::string& what) {
  std::size_t at = 0;
  if (IsValidUtf8(text, &at)) return;
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  char buf[128];
  std::snprintf(buf, sizeof buf, ":%zu: invalid UTF-8 (byte 0x%02X at byte column %zu)", line,
                static_cast<unsigned>(static_cast<unsigned char>(text[at])), col);
  throw InputError(what + buf + ": text must be UTF-8 (names and strings are written to JSON outputs)");
}

}  // namespace hullopt::io
