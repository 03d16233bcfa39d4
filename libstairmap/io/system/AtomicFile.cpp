#include "io/system/AtomicFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace stairmap::io {
namespace {

std::string errnoText() { return std::strerror(errno); }

std::string directoryOf(const std::string& path) {
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

/// Writes all bytes to fd and fsyncs it; returns an error text or "" on success.
std::string writeAndSync(int fd, const std::string& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return "write failed: " + errnoText();
        done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0) return "fsync failed: " + errnoText();
    return "";
}

void syncDirectory(const std::string& dir) {
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0) return;  // best effort: the rename itself already happened
    ::fsync(fd);
    ::close(fd);
}

}  // namespace

void writeTextFileAtomic(const std::string& path, const std::string& text) {
    // One fixed temp name: a temp file left by a killed run is simply overwritten next time.
    const std::string tmp = path + ".tmp";
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) {
        throw std::runtime_error(path + ": cannot create temporary file " + tmp + ": " +
                                 errnoText());
    }
    std::string error = writeAndSync(fd, text);
    if (::close(fd) != 0 && error.empty()) error = "close failed: " + errnoText();
    if (error.empty() && ::rename(tmp.c_str(), path.c_str()) != 0) {
        error = "rename of " + tmp + " failed: " + errnoText();
    }
    if (!error.empty()) {
        ::unlink(tmp.c_str());
        throw std::runtime_error(path + ": " + error + " (previous file left unchanged)");
    }
    syncDirectory(directoryOf(path));
}

}  // namespace stairmap::io
