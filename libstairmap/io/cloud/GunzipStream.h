#pragma once
// Streaming gzip (RFC 1952) input: an std::istream that inflates one gzip member from a source
// stream on demand, so a reader parses a .pcd.gz like a plain file without holding the whole
// decompressed data. Memory: two 64 KiB buffers and zlib's 32 KiB window, whatever the data.
//
// Budget: at most `max_bytes` decompressed bytes are produced; a stream that would inflate further
// fails with "decompresses to more than N bytes" (a guard against decompression bombs). A reader
// that knows how much data its header declares stops long before that (see CloudFile.h).
//
// Errors never throw from inside the stream (std::istream would swallow them): the stream reports
// end of data and remembers the problem; `error()` tells it, `finish()` throws it. Strict like
// gunzipBuffer: one complete member with a matching CRC and nothing after it.

#include <cstddef>
#include <istream>
#include <memory>
#include <string>

namespace stairmap::io {

class GunzipStreamBuf;

class GunzipStream : public std::istream {
public:
    /// Inflates from `source` (positioned at the gzip signature), which must outlive this stream.
    GunzipStream(std::istream& source, std::size_t max_bytes);
    ~GunzipStream() override;

    /// The problem that ended the stream early ("truncated gzip data", ...); empty if none.
    const std::string& error() const;

    /// Inflates (and discards) whatever the reader left unread, then throws std::runtime_error if
    /// the gzip stream is bad: not gzip, truncated, corrupt, over the budget or followed by data.
    void finish();

private:
    std::unique_ptr<GunzipStreamBuf> buf_;
};

}  // namespace stairmap::io
