#pragma once
// A file that another process is still writing, read as an MRPT stream: Read() returns what is
// there and, at the current end of the file, WAITS for the rest instead of reporting a short read.
// So a rawlog object the writer has only half flushed is read whole once its tail arrives, and the
// MRPT deserializer never sees a partial object as corruption while the file still grows.
//
// Read() gives up (returns fewer bytes than asked, which MRPT reports as the end of the data) only
// when the file has not grown for `idle_timeout_s` or a stop is requested. Whether that end falls
// between objects (a clean end) or inside one (a truncated file) is for the reader to judge.
// Plain files only: a gzip stream cannot be read while it is written.

#include <mrpt/io/CStream.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>

namespace stairmap::io {

struct GrowingFileParams {
    double idle_timeout_s = 5.0;  ///< [s] no growth for this long while waiting: the stream ends
    double poll_period_s = 0.05;  ///< [s] how often growth and the stop flag are checked
};

/// Why the stream stopped waiting (the last short read).
enum class GrowingFileEnd { None, IdleTimeout, Stopped, Shrank };

class GrowingFileStream : public mrpt::io::CStream {
public:
    /// Opens `path`. Throws std::runtime_error "<path>: ..." if it cannot be opened.
    GrowingFileStream(const std::string& path, const GrowingFileParams& params,
                      const std::atomic<bool>& stop);
    ~GrowingFileStream() override;
    GrowingFileStream(const GrowingFileStream&) = delete;
    GrowingFileStream& operator=(const GrowingFileStream&) = delete;

    /// Up to Count bytes; fewer only at an end (see GrowingFileEnd). Throws std::runtime_error
    /// naming the file on a read error.
    size_t Read(void* buffer, size_t count) override;
    /// Not supported (read-only): throws.
    size_t Write(const void* buffer, size_t count) override;
    /// Not supported (a followed file is read front to back): throws.
    uint64_t Seek(int64_t offset, CStream::TSeekOrigin origin) override;
    /// The file's size now [bytes].
    uint64_t getTotalBytesCount() const override;
    /// Bytes read so far.
    uint64_t getPosition() const override { return position_; }
    std::string getStreamDescription() const override;

    /// Why the last read stopped short (None while it never did).
    GrowingFileEnd end() const { return end_; }
    /// Bytes in the file not read yet (how far the reader is behind the writer).
    uint64_t bytesBehind() const;

private:
    bool waitForGrowth();

    std::string path_;
    GrowingFileParams params_;
    const std::atomic<bool>& stop_;
    int fd_ = -1;
    uint64_t position_ = 0;
    uint64_t last_size_ = 0;
    std::chrono::steady_clock::time_point last_growth_;
    GrowingFileEnd end_ = GrowingFileEnd::None;
};

}  // namespace stairmap::io
