#pragma once
// One writer per output folder: an exclusive flock(2) on "<dir>/.stairmap.lock", which holds the
// owner's pid. The lock belongs to the open file, so the kernel releases it when the process ends
// in any way (even SIGKILL); a stale lock file is simply locked again by the next run.
// The owner removes the lock file when it releases the lock. A process that locked a file which
// was removed meanwhile notices (the path names another inode) and tries again.

#include <string>

namespace stairmap::io {

class DirectoryLock {
  public:
    /// Locks `dir` (which must exist). Throws std::runtime_error "<dir>: ... (pid N) ..." naming
    /// the process that holds it, or naming the lock file if it cannot be created.
    explicit DirectoryLock(const std::string& dir);
    ~DirectoryLock();
    DirectoryLock(const DirectoryLock&) = delete;
    DirectoryLock& operator=(const DirectoryLock&) = delete;

    const std::string& path() const { return path_; }
    static constexpr const char* kFileName = ".stairmap.lock";

  private:
    bool tryLock(const std::string& dir);
    std::string path_;
    int fd_ = -1;
};

}  // namespace stairmap::io
