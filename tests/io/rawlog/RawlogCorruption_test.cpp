// Bad rawlog files: truncated, random bytes, missing, empty. Never a crash; errors name the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "RawlogTestUtil.h"
#include "io/rawlog/RawlogScanSource.h"

using namespace stairmap;
using namespace stairmap::io;
using namespace stairmap::test;
using mrpt::poses::CPose3D;

namespace {

// 10 scans of 200 points each, with poses; returns the file size after each object pair.
std::vector<std::uintmax_t> writeTenScans(const std::string& path) {
    std::vector<std::uintmax_t> sizes;
    std::vector<Eigen::Vector3f> pts;
    for (int k = 0; k < 200; ++k) pts.emplace_back(1.0f + 0.01f * k, 0.5f, 0.2f);
    for (int i = 0; i < 10; ++i) {
        RawlogWriter w(path + ".part" + std::to_string(i), false);
        w << *makePoseObs(i, CPose3D(i, 0, 0, 0, 0, 0));
        w << *makeCloudObs(i, CPose3D(), pts);
    }
    std::ofstream out(path, std::ios::binary);
    for (int i = 0; i < 10; ++i) {
        const std::string part = path + ".part" + std::to_string(i);
        std::ifstream in(part, std::ios::binary);
        out << in.rdbuf();
        out.flush();
        sizes.push_back(std::filesystem::file_size(path));
    }
    return sizes;
}

void cutFile(const std::string& from, const std::string& to, std::uintmax_t bytes) {
    std::ifstream in(from, std::ios::binary);
    std::vector<char> buf(bytes);
    in.read(buf.data(), std::streamsize(bytes));
    std::ofstream(to, std::ios::binary).write(buf.data(), std::streamsize(bytes));
}

}  // namespace

TEST(RawlogCorruption, TruncatedFileReturnsGoodScansThenNamesIndex) {
    const std::string dir = scratchDir();
    const auto sizes = writeTenScans(dir + "/full.rawlog");
    // Cut in the middle of scan 6's point cloud (object index 13).
    const std::uintmax_t cut = sizes[5] + (sizes[6] - sizes[5]) * 3 / 4;
    const std::string path = dir + "/cut.rawlog";
    cutFile(dir + "/full.rawlog", path, cut);

    RawlogScanSource src(path);
    std::size_t good = 0;
    try {
        while (auto s = src.next()) {
            EXPECT_EQ(s->points_robot.size(), 200u);
            EXPECT_NEAR(s->T_world_robot.translation().x(), double(good), 1e-9);
            ++good;
        }
        FAIL() << "a truncated file must raise an error";
    } catch (const std::runtime_error& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(path), std::string::npos) << msg;
        EXPECT_NE(msg.find("truncated or corrupt at object index 13"), std::string::npos) << msg;
        EXPECT_NE(msg.find("scan index 6"), std::string::npos) << msg;
    }
    EXPECT_EQ(good, 6u);  // every scan before the cut
    EXPECT_THROW(src.next(), std::runtime_error);  // stays in error
}

TEST(RawlogCorruption, CutAtObjectBoundaryIsACleanEnd) {
    const std::string dir = scratchDir();
    const auto sizes = writeTenScans(dir + "/full.rawlog");
    cutFile(dir + "/full.rawlog", dir + "/cut.rawlog", sizes[3]);
    RawlogScanSource src(dir + "/cut.rawlog");
    std::size_t n = 0;
    while (src.next()) ++n;
    EXPECT_EQ(n, 4u);
}

TEST(RawlogCorruption, TruncatedGzFileReportsError) {
    const std::string dir = scratchDir();
    const std::string full = dir + "/full.rawlog.gz";
    {
        RawlogWriter w(full, true);
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> u(-5, 5);
        for (int i = 0; i < 6; ++i) {
            std::vector<Eigen::Vector3f> pts;  // fresh random points: scans compress alike
            for (int k = 0; k < 2000; ++k) pts.emplace_back(u(rng), u(rng), u(rng));
            w << *makePoseObs(i, CPose3D(i, 0, 0, 0, 0, 0));
            w << *makeCloudObs(i, CPose3D(), pts);
        }
    }
    {
        RawlogScanSource whole(full);
        std::size_t n = 0;
        while (whole.next()) ++n;
        ASSERT_EQ(n, 6u);
    }
    const auto size = std::filesystem::file_size(full);
    cutFile(full, dir + "/cut.rawlog.gz", size / 2);
    RawlogScanSource src(dir + "/cut.rawlog.gz");
    std::size_t n = 0;
    try {
        while (src.next()) ++n;
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("truncated or corrupt"), std::string::npos) << e.what();
    }
    EXPECT_GE(n, 1u);
    EXPECT_LT(n, 6u);
}

TEST(RawlogCorruption, RandomBytesThrowNamingFile) {
    const std::string path = scratchDir() + "/random.rawlog";
    std::mt19937 rng(42);
    std::ofstream out(path, std::ios::binary);
    for (int i = 0; i < 4096; ++i) out.put(char(rng() & 0xFF));
    out.close();
    RawlogScanSource src(path);
    try {
        while (src.next()) {
        }
        FAIL() << "random bytes must not read as a valid rawlog";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("object index 0"), std::string::npos) << e.what();
    }
}

TEST(RawlogCorruption, MissingFileThrowsInConstructor) {
    const std::string path = scratchDir() + "/does_not_exist.rawlog";
    try {
        RawlogScanSource src(path);
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    const std::string dir = scratchDir();
    EXPECT_THROW(RawlogScanSource{dir}, std::runtime_error);  // a directory
}

TEST(RawlogCorruption, EmptyFileHasNoScans) {
    const std::string path = scratchDir() + "/empty.rawlog";
    std::ofstream(path).close();
    RawlogScanSource src(path);
    EXPECT_FALSE(src.next().has_value());
    EXPECT_EQ(src.stats().objects_read, 0u);
}

TEST(RawlogCorruption, OverwrittenBytesNeverCrash) {
    const std::string dir = scratchDir();
    const auto sizes = writeTenScans(dir + "/full.rawlog");
    std::ifstream in(dir + "/full.rawlog", std::ios::binary);
    const std::vector<char> original((std::istreambuf_iterator<char>(in)), {});
    std::mt19937 rng(2024);
    for (int trial = 0; trial < 40; ++trial) {
        std::vector<char> bytes = original;
        const std::size_t at = rng() % bytes.size();
        const std::size_t len = 1 + rng() % 16;
        for (std::size_t k = at; k < std::min(bytes.size(), at + len); ++k) bytes[k] = char(rng());
        const std::string path = dir + "/damaged.rawlog";
        std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
        RawlogScanSource src(path);
        std::size_t scans = 0;
        try {
            while (auto s = src.next()) {
                ++scans;
                for (const auto& p : s->points_robot) ASSERT_TRUE(p.allFinite());
            }
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
        EXPECT_LE(scans, 10u) << "trial " << trial;
    }
}
