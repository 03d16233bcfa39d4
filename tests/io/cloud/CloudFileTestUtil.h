#pragma once
// Helpers for the cloud-file tests: scratch folders, raw file writing, seeded clouds.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>

#include "core/PointCloud.h"

namespace stairmap::test {

/// A fresh, empty folder STAIRMAP_TEST_TMP/<suite>/<name>.<pid>. The pid keeps tests that ctest
/// runs in parallel processes apart (two CloudFileLimits tests sharing "f" removed each other's
/// files: "cannot remove all: No such file or directory" in a CI run).
inline std::string scratchDir(const std::string& suite, const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::path(STAIRMAP_TEST_TMP) / suite / (name + "." + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

inline void writeRaw(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    ASSERT_TRUE(out.good()) << path;
}

/// Seeded random cloud with a spread of magnitudes (and exact small values).
inline PointCloud randomCloud(std::size_t n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> coord(-50.0f, 50.0f);
    PointCloud cloud;
    for (std::size_t i = 0; i < n; ++i) cloud.emplace_back(coord(rng), coord(rng), coord(rng) * 1e-3f);
    cloud.emplace_back(0.0f, -0.0f, 1.0f);
    cloud.emplace_back(1e-7f, 12345.678f, -3.25f);
    return cloud;
}

/// Packs a value's little-endian bytes into a string.
template <typename T>
std::string bytesOf(T value) {
    return std::string(reinterpret_cast<const char*>(&value), sizeof(T));
}

/// Runs `read`, expects a std::runtime_error whose message starts with `prefix` and contains
/// `phrase`; returns the message.
inline std::string expectReadError(const std::function<void()>& read, const std::string& prefix,
                                   const std::string& phrase) {
    try {
        read();
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(prefix, 0), 0u) << "message should start with '" << prefix << "': " << what;
        EXPECT_NE(what.find(phrase), std::string::npos) << "message should say '" << phrase << "': " << what;
        return what;
    }
    ADD_FAILURE() << "expected a std::runtime_error saying '" << phrase << "'";
    return {};
}

}  // namespace stairmap::test
