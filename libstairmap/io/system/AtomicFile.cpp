#include "io/system/AtomicFile.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <new>
#include <regex>
#include <stdexcept>

namespace stairmap::io {
namespace {

namespace fs = std::filesystem;

std::string errnoText() { return std::strerror(errno); }

std::string directoryOf(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? "." : parent.string();
}

void syncDirectory(const std::string& dir) {
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;  // best effort: the rename itself already happened
    ::fsync(fd);
    ::close(fd);
}

/// Writes all bytes to a new file `path`; throws naming it.
void writeAll(const std::string& path, const std::string& bytes) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0)
        throw std::runtime_error("cannot create temporary file " + path + ": " + errnoText());
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const std::string error = "write failed: " + errnoText();
            ::close(fd);
            throw std::runtime_error(error);
        }
        done += static_cast<std::size_t>(n);
    }
    if (::close(fd) != 0) throw std::runtime_error("close failed: " + errnoText());
}

const std::regex& tempNamePattern() {
    static const std::regex pattern(R"(\..+\.tmp-([0-9]{1,9})-[0-9]+(\.[^.]*)?)");
    return pattern;
}

}  // namespace

std::string uniqueTempPath(const std::string& path) {
    static std::atomic<unsigned long> counter{0};
    const fs::path p(path);
    const std::string name = "." + p.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                             std::to_string(++counter) + p.extension().string();
    return (p.parent_path() / name).string();
}

bool isTempFileName(const std::string& filename) {
    return std::regex_match(filename, tempNamePattern());
}

void syncFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw std::runtime_error(path + ": cannot open to sync: " + errnoText());
    const bool ok = ::fsync(fd) == 0;
    const std::string error = ok ? "" : errnoText();
    ::close(fd);
    if (!ok) throw std::runtime_error(path + ": fsync failed: " + error);
}

void renameDurably(const std::string& from, const std::string& to) {
    if (::rename(from.c_str(), to.c_str()) != 0)
        throw std::runtime_error("rename of " + from + " to " + to + " failed: " + errnoText());
    syncDirectory(directoryOf(to));
}

void writeFileAtomic(const std::string& path,
                     const std::function<void(const std::string&)>& write) {
    const std::string tmp = uniqueTempPath(path);
    try {
        write(tmp);
        syncFile(tmp);
        renameDurably(tmp, path);
    } catch (const std::bad_alloc&) {
        ::unlink(tmp.c_str());
        throw std::runtime_error(path +
                                 ": out of memory while writing it (previous file left unchanged)");
    } catch (const std::exception& e) {
        ::unlink(tmp.c_str());
        throw std::runtime_error(path + ": " + e.what() + " (previous file left unchanged)");
    } catch (...) {
        ::unlink(tmp.c_str());  // no temp file stays behind, whatever was thrown
        throw;
    }
}

void writeTextFileAtomic(const std::string& path, const std::string& text) {
    writeFileAtomic(path, [&](const std::string& tmp) { writeAll(tmp, text); });
}

int removeStaleTempFiles(const std::string& dir) {
    int removed = 0;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        std::smatch m;
        const std::string name = it->path().filename().string();
        if (!std::regex_match(name, m, tempNamePattern())) continue;
        const long pid = std::stol(m[1].str());
        const bool alive =
            pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
        if (!alive && ::unlink(it->path().c_str()) == 0) ++removed;
    }
    return removed;
}

}  // namespace stairmap::io
