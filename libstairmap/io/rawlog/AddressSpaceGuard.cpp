#include "io/rawlog/AddressSpaceGuard.h"

#include <sys/resource.h>
#include <unistd.h>

#include <fstream>

namespace stairmap::io {
namespace {

// Current virtual memory size from /proc/self/statm (first field, in pages); 0 if unknown.
std::uint64_t mappedBytes() {
    std::ifstream statm("/proc/self/statm");
    std::uint64_t pages = 0;
    if (!(statm >> pages)) return 0;
    return pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

}  // namespace

AddressSpaceGuard::AddressSpaceGuard(std::uint64_t headroom_bytes) {
    if (headroom_bytes == 0) return;
    const std::uint64_t mapped = mappedBytes();
    rlimit lim{};
    if (mapped == 0 || getrlimit(RLIMIT_AS, &lim) != 0) return;
    const std::uint64_t wanted = mapped + headroom_bytes;
    if (lim.rlim_cur != RLIM_INFINITY && lim.rlim_cur <= wanted) return;  // already tighter
    old_soft_ = lim.rlim_cur;
    lim.rlim_cur = wanted;
    active_ = setrlimit(RLIMIT_AS, &lim) == 0;
}

AddressSpaceGuard::~AddressSpaceGuard() {
    if (!active_) return;
    rlimit lim{};
    if (getrlimit(RLIMIT_AS, &lim) != 0) return;
    lim.rlim_cur = old_soft_;
    setrlimit(RLIMIT_AS, &lim);
}

}  // namespace stairmap::io
