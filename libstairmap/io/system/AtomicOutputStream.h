#pragma once
// A file written as a stream over a whole run (e.g. detections.jsonl, one line per detection)
// that replaces its target only when committed: until then the data goes to a unique temp file
// next to it (AtomicFile.h), and the previous file stays whole. Destroying an uncommitted stream
// (an error, an exception unwinding) removes the temp file.

#include <fstream>
#include <string>

namespace stairmap::io {

class AtomicOutputStream {
  public:
    /// Creates the temp file for `path`. Throws std::runtime_error naming `path`.
    explicit AtomicOutputStream(std::string path);
    ~AtomicOutputStream();
    AtomicOutputStream(const AtomicOutputStream&) = delete;
    AtomicOutputStream& operator=(const AtomicOutputStream&) = delete;

    std::ostream& stream() { return out_; }
    /// Flushes, syncs and renames the temp file over the target. Throws std::runtime_error naming
    /// the target (the temp file is then removed and the previous file left unchanged).
    void commit();
    const std::string& path() const { return path_; }

  private:
    std::string path_, tmp_;
    std::ofstream out_;
    bool committed_ = false;
};

}  // namespace stairmap::io
