#pragma once
// Memory use of this process, from /proc/self/status (Linux).

#include <cstddef>

namespace stairmap::io {

/// Peak resident set size (VmHWM) [bytes]; 0 if unavailable.
std::size_t peakRssBytes();
/// Current resident set size (VmRSS) [bytes]; 0 if unavailable.
std::size_t currentRssBytes();

}  // namespace stairmap::io
