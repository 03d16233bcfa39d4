#pragma once
// Runs the built `stairmap` (STAIRMAP_BIN) as a child process and reports its exit code, output
// and peak resident memory (ru_maxrss from wait4, the child alone). The child runs under an
// address-space limit and a CPU-time limit so that a test on a memory-hungry or looping build
// ends by itself (with bad_alloc or SIGXCPU) instead of exhausting the host.

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "CliRunner.h"

namespace stairmap::test {

struct MeasuredRun {
    int exit_code = -1;
    std::string out, err;
    long peak_rss_kb = 0;  ///< [KiB] ru_maxrss of the child
    double peakRssMb() const { return peak_rss_kb / 1024.0; }
};

#if defined(__SANITIZE_ADDRESS__)
/// ASan reserves terabytes of address space for its shadow memory, so an address-space limit would
/// stop the child before main(); under ASan the peak-RSS checks stand alone.
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif

struct ChildLimits {
    /// far above the 512 MB target; none under ASan (see kAddressSanitizer)
    rlim_t address_space_bytes = kAddressSanitizer ? RLIM_INFINITY : rlim_t{3} << 30;
    rlim_t cpu_seconds = 60;
};

/// Runs `stairmap args...` with stdout/stderr in `dir`.
inline MeasuredRun runMeasured(const std::vector<std::string>& args, const std::string& dir,
                               const ChildLimits& limits = {}) {
    const std::string out = dir + "/stdout.txt", err = dir + "/stderr.txt";
    const pid_t pid = fork();
    if (pid == 0) {
        const rlimit as{limits.address_space_bytes, limits.address_space_bytes};
        const rlimit cpu{limits.cpu_seconds, limits.cpu_seconds};
        setrlimit(RLIMIT_AS, &as);
        setrlimit(RLIMIT_CPU, &cpu);
        dup2(open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 1);
        dup2(open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 2);
        std::vector<char*> argv{const_cast<char*>(STAIRMAP_BIN)};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(STAIRMAP_BIN, argv.data());
        _exit(127);
    }
    MeasuredRun r;
    int status = 0;
    rusage usage{};
    if (pid > 0 && wait4(pid, &status, 0, &usage) == pid) {
        r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        r.peak_rss_kb = usage.ru_maxrss;
    }
    r.out = readText(out);
    r.err = readText(err);
    return r;
}

}  // namespace stairmap::test
