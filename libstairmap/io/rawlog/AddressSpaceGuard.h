#pragma once
// Caps the process's virtual address space growth while a block of code runs (Linux RLIMIT_AS),
// so that a corrupt size field in a file makes the deserializer's allocation fail with
// std::bad_alloc instead of the whole process being killed for lack of memory.
//
// Why: MRPT's deserializers resize vectors to the sizes written in the file before reading the
// data; one flipped byte in a point count asks for up to 16 GB per coordinate array, which Linux
// grants (overcommit) and then kills the process while zero-filling it.
// Process-wide while active: meant for single-threaded reading. Restores the previous limit.

#include <cstdint>

namespace stairmap::io {

class AddressSpaceGuard {
public:
    /// Allows `headroom_bytes` of address space beyond what is mapped now. headroom 0: no-op.
    explicit AddressSpaceGuard(std::uint64_t headroom_bytes);
    ~AddressSpaceGuard();
    AddressSpaceGuard(const AddressSpaceGuard&) = delete;
    AddressSpaceGuard& operator=(const AddressSpaceGuard&) = delete;

private:
    bool active_ = false;
    std::uint64_t old_soft_ = 0;
};

}  // namespace stairmap::io
