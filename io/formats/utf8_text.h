#pragma once
// UTF-8 validity of text read from input files and command lines: names and strings end up in JSON outputs,
// which must be valid UTF-8, so invalid bytes are refused where they are read (with the line), not when a
// file is written.
#include <cstddef>
#include <string>

namespace hullopt::io {

/// True if text is well-formed UTF-8 (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF). Otherwise
/// false, with *bad_offset the byte offset of the first invalid sequence.
bool IsValidUtf8(const std::string& text, std::size_t* bad_offset = nullptr);

/// Throws InputError "<what>:<line>: invalid UTF-8 (byte 0xNN at column C) ..." if text is not valid UTF-8.
/// line counts from 1 in text itself.
void RequireUtf8(const std::string& text, const std::string& what);

}  // namespace hullopt::io
