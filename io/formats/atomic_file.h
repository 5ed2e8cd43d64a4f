#pragma once
// Every output file is written whole or not at all: the text goes to a temporary file in the same folder,
// is fsync'd, and is renamed over the target (rename(2) is atomic within a file system). A run killed while
// writing leaves the previous version of the file (or none) and at most a stray temporary, never half a file.
#include <string>

namespace hullopt::io {

/// Writes `content` (text or binary) to `path` atomically as described above. Throws InputError naming the
/// path if it cannot be written; the temporary file is removed then.
void WriteFileAtomically(const std::string& path, const std::string& content);

}  // namespace hullopt::io
