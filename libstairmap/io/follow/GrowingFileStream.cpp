#include "io/follow/GrowingFileStream.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <thread>

namespace stairmap::io {
namespace {

uint64_t fileSize(int fd) {
    struct stat st {};
    return ::fstat(fd, &st) == 0 ? static_cast<uint64_t>(st.st_size) : 0;
}

}  // namespace

GrowingFileStream::GrowingFileStream(const std::string& path, const GrowingFileParams& params,
                                     const std::atomic<bool>& stop)
    : path_(path), params_(params), stop_(stop) {
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) throw std::runtime_error(path + ": cannot open: " + std::strerror(errno));
    struct stat st {};
    if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd_);
        throw std::runtime_error(path + ": not a regular file (only files can be followed)");
    }
    last_size_ = static_cast<uint64_t>(st.st_size);
    last_growth_ = std::chrono::steady_clock::now();
}

GrowingFileStream::~GrowingFileStream() {
    if (fd_ >= 0) ::close(fd_);
}

// Waits until the file is longer than what was read, or an end: idle timeout, stop, or the file
// got shorter than what was already read (truncated or replaced by its writer).
bool GrowingFileStream::waitForGrowth() {
    const auto poll = std::chrono::duration<double>(params_.poll_period_s);
    for (;;) {
        const uint64_t size = fileSize(fd_);
        const auto now = std::chrono::steady_clock::now();
        if (size != last_size_) {
            last_size_ = size;
            last_growth_ = now;
        }
        if (size < position_) {
            end_ = GrowingFileEnd::Shrank;
            return false;
        }
        if (size > position_) return true;
        if (stop_.load()) {
            end_ = GrowingFileEnd::Stopped;
            return false;
        }
        if (std::chrono::duration<double>(now - last_growth_).count() >= params_.idle_timeout_s) {
            end_ = GrowingFileEnd::IdleTimeout;
            return false;
        }
        std::this_thread::sleep_for(poll);
    }
}

size_t GrowingFileStream::Read(void* buffer, size_t count) {
    auto* out = static_cast<char*>(buffer);
    size_t done = 0;
    while (done < count) {
        const ssize_t n = ::pread(fd_, out + done, count - done, static_cast<off_t>(position_));
        if (n < 0) {
            if (errno == EINTR) continue;
            throw std::runtime_error(path_ + ": read error: " + std::strerror(errno));
        }
        if (n > 0) {
            done += static_cast<size_t>(n);
            position_ += static_cast<uint64_t>(n);
            continue;
        }
        if (!waitForGrowth()) break;  // at the end of what is written: wait for the writer
    }
    return done;
}

size_t GrowingFileStream::Write(const void*, size_t) {
    throw std::runtime_error(path_ + ": a followed file is read-only");
}

uint64_t GrowingFileStream::Seek(int64_t, CStream::TSeekOrigin) {
    throw std::runtime_error(path_ + ": a followed file cannot seek");
}

uint64_t GrowingFileStream::getTotalBytesCount() const { return fileSize(fd_); }

std::string GrowingFileStream::getStreamDescription() const { return path_ + " (followed)"; }

uint64_t GrowingFileStream::bytesBehind() const {
    const uint64_t size = fileSize(fd_);
    return size > position_ ? size - position_ : 0;
}

}  // namespace stairmap::io
