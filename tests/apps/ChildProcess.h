#pragma once
// Test helper: runs the built `stairmap` binary as a child process that the test can signal,
// with extra environment variables and an optional address-space limit, and waits for it with a
// deadline (a child still running then is killed, so a test always ends).

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace stairmap::test {

struct ChildOptions {
    std::vector<std::string> env;  ///< "NAME=value" added to the child's environment
    std::string stdout_path = "/dev/null";
    std::string stderr_path = "/dev/null";
    long address_space_mb = 0;  ///< RLIMIT_AS of the child [MiB]; 0 = unchanged
};

/// Starts `stairmap <args...>`; returns its pid.
inline pid_t spawnStairmap(const std::vector<std::string>& args, const ChildOptions& options = {}) {
    const pid_t pid = ::fork();
    if (pid != 0) return pid;
    // Child: only async-signal-safe work until exec (open, dup2, setrlimit, putenv, execv).
    for (const auto& e : options.env) ::putenv(const_cast<char*>(e.c_str()));
    const int out = ::open(options.stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(options.stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(err, STDERR_FILENO);
    if (options.address_space_mb > 0) {
        const rlim_t bytes = static_cast<rlim_t>(options.address_space_mb) << 20;
        const rlimit limit{bytes, bytes};
        ::setrlimit(RLIMIT_AS, &limit);
    }
    std::vector<char*> argv{const_cast<char*>(STAIRMAP_BIN)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(STAIRMAP_BIN, argv.data());
    ::_exit(127);
}

/// Exit status of `pid` (128 + signal if it died of one), waiting at most `timeout`; a child
/// still running then is killed and -1 returned.
inline int waitForExit(pid_t pid, std::chrono::milliseconds timeout = std::chrono::seconds(120)) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    int status = 0;
    while (::waitpid(pid, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            return -1;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// Waits until the file at `path` is non-empty (e.g. a child's first progress output), at most
/// `timeout`. Returns whether it did.
inline bool waitForOutput(const std::string& path, std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
        std::ifstream in(path);
        if (in.peek() != std::ifstream::traits_type::eof()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
}

inline std::string fileText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace stairmap::test
