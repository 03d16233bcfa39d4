#pragma once
// Small output-file helpers for the mapper's writers.

#include <string>

namespace stairmap::io {

/// Writes `text` to `path` atomically: a temp file next to it, flushed, then renamed over `path`,
/// so readers never see a half-written file. Throws std::runtime_error naming the path.
void writeTextFileAtomic(const std::string& path, const std::string& text);

}  // namespace stairmap::io
