#pragma once
// Crash-safe replacement of output files (landmark maps, stats).

#include <string>

namespace stairmap::io {

/// Writes `text` to `path` atomically: a temp file `path.tmp` next to it, fsync'ed, renamed over
/// `path`, then the directory fsync'ed. A kill at any moment leaves either the old or the new
/// file, never a half-written one. Throws std::runtime_error naming the path (the old file is
/// left unchanged).
void writeTextFileAtomic(const std::string& path, const std::string& text);

}  // namespace stairmap::io
