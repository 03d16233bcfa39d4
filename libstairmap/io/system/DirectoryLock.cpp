#include "io/system/DirectoryLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <thread>

namespace stairmap::io {
namespace {

/// The pid written by the holder; it writes right after locking, so wait a moment for it.
std::string holderPid(int fd) {
    for (int attempt = 0; attempt < 20; ++attempt) {
        char text[32] = {};
        const ssize_t n = ::pread(fd, text, sizeof(text) - 1, 0);
        if (n > 0) {
            std::string pid(text, static_cast<std::size_t>(n));
            while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
            return pid;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return "unknown";
}

bool sameFile(int fd, const std::string& path) {
    struct stat by_fd {
    }, by_path{};
    return ::fstat(fd, &by_fd) == 0 && ::stat(path.c_str(), &by_path) == 0 &&
           by_fd.st_dev == by_path.st_dev && by_fd.st_ino == by_path.st_ino;
}

}  // namespace

DirectoryLock::DirectoryLock(const std::string& dir)
    : path_((std::filesystem::path(dir) / kFileName).string()) {
    for (int attempt = 0; attempt < 100; ++attempt) {
        if (tryLock(dir)) return;
    }
    throw std::runtime_error(path_ +
                             ": cannot take the output folder's lock (it keeps being replaced)");
}

bool DirectoryLock::tryLock(const std::string& dir) {
    const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
        throw std::runtime_error(path_ + ": cannot create the lock file: " + std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const int error = errno;
        const std::string pid = error == EWOULDBLOCK ? holderPid(fd) : "";
        ::close(fd);
        if (error != EWOULDBLOCK)
            throw std::runtime_error(path_ + ": cannot lock: " + std::strerror(error));
        throw std::runtime_error(dir + ": another stairmap run (pid " + pid +
                                 ") is writing to this output folder (lock " + path_ +
                                 "); wait for it to finish or choose another --out");
    }
    if (!sameFile(fd, path_)) {  // the previous owner removed it between our open and flock
        ::close(fd);
        return false;
    }
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) < 0) {
        const std::string error = std::strerror(errno);
        ::close(fd);
        throw std::runtime_error(path_ + ": cannot write the lock file: " + error);
    }
    fd_ = fd;
    return true;
}

DirectoryLock::~DirectoryLock() {
    if (fd_ < 0) return;
    ::unlink(path_.c_str());  // while still locked: a waiting process then sees another inode
    ::close(fd_);
}

}  // namespace stairmap::io
