#pragma once
// Helpers shared by the libFuzzer drivers: the input as a stream or as a file with a given
// extension (readers that dispatch on the file name), and the one rule every driver checks.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace stairmap::fuzz {

inline std::string asString(const std::uint8_t* data, std::size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

/// Writes the input to a per-process scratch file ending in `extension` and returns its path
/// (rewritten on every call; /dev/shm when present so the disk is not worn).
inline std::string asFile(const std::uint8_t* data, std::size_t size, const std::string& extension) {
    const char* dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    const std::string path = std::string(dir) + "/stairmap_fuzz_" + std::to_string(getpid()) + extension;
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), std::streamsize(size));
    return path;
}

/// Bad input must end in an exception that says something: an empty message is a finding.
inline void requireMessage(const std::exception& e) {
    if (e.what() == nullptr || e.what()[0] == '\0') __builtin_trap();
}

}  // namespace stairmap::fuzz
