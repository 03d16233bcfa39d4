#pragma once
// Test helper: runs a program as a child process and reports its exit code and peak RSS
// (wait4's rusage of that one child, so earlier children of the test process do not count).

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

namespace stairmap::testing {

struct ChildRun {
    int exit_code = -1;      ///< exit status, or 128 + signal
    long peak_rss_kb = -1;   ///< [KiB] ru_maxrss of the child
};

/// Runs argv[0] with argv (no shell), stdout and stderr to `log_path`.
inline ChildRun runMeasured(const std::vector<std::string>& argv, const std::string& log_path) {
    ChildRun run;
    const pid_t pid = ::fork();
    if (pid < 0) return run;
    if (pid == 0) {
        const int fd = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            ::dup2(fd, 1);
            ::dup2(fd, 2);
        }
        std::vector<char*> args;
        for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        ::execv(args[0], args.data());
        ::_exit(127);
    }
    int status = 0;
    rusage usage{};
    if (::wait4(pid, &status, 0, &usage) != pid) return run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    run.peak_rss_kb = usage.ru_maxrss;
    return run;
}

}  // namespace stairmap::testing
