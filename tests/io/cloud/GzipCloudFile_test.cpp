// Gzipped cloud files (.pcd.gz, .ply.gz, .xyz.gz): exact round trips, reproducible bytes, and a
// clear "<path>: problem" error for every kind of bad compressed input.

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "CloudFileTestUtil.h"
#include "io/cloud/CloudFile.h"
#include "io/cloud/GzipBuffer.h"

namespace stairmap::io {
namespace {

using test::expectReadError;
using test::randomCloud;
using test::scratchDir;
using test::writeRaw;

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string plainPcd(const PointCloud& cloud) {
    std::ostringstream out(std::ios::binary);
    writePcd(out, cloud, CloudFileEncoding::Binary);
    return out.str();
}

TEST(GzipBuffer, RoundTripsAndCompressesRepetitiveData) {
    std::string data;
    for (int i = 0; i < 5000; ++i) data += "0.125 -3.5 1\n";
    const std::string gz = gzipBuffer(data);
    EXPECT_LT(gz.size(), data.size() / 20);
    EXPECT_EQ(static_cast<unsigned char>(gz[0]), 0x1f);
    EXPECT_EQ(gunzipBuffer(gz), data);
    EXPECT_EQ(gunzipBuffer(gzipBuffer("")), "");
}

TEST(GzipBuffer, OutputIsReproducible) {
    const std::string data = plainPcd(randomCloud(500, 3));
    EXPECT_EQ(gzipBuffer(data, 9), gzipBuffer(data, 9));  // no time stamp or name in the header
    EXPECT_THROW(gzipBuffer(data, 0), std::invalid_argument);
    EXPECT_THROW(gzipBuffer(data, 10), std::invalid_argument);
}

TEST(GzipBuffer, RejectsPlainTruncatedCorruptAndTrailingData) {
    const std::string data = plainPcd(randomCloud(2000, 4));
    const std::string gz = gzipBuffer(data);
    auto expectError = [](const std::string& bytes, const std::string& phrase) {
        expectReadError([&] { gunzipBuffer(bytes); }, "", phrase);
    };
    expectError(data, "not gzip data");
    expectError("", "not gzip data");
    expectError(gz.substr(0, gz.size() / 2), "truncated gzip data");
    expectError(gz.substr(0, gz.size() - 4), "truncated gzip data");  // no length field
    std::string bad_crc = gz;
    bad_crc[bad_crc.size() - 6] ^= 0x5a;  // inside the CRC-32 of the trailer
    expectError(bad_crc, "corrupt gzip data");
    std::string bad_method = gz;
    bad_method[2] = 7;  // compression method other than deflate
    expectError(bad_method, "corrupt gzip data");
    expectError(gz + "junk", "trailing data after the gzip stream");
}

TEST(GzipBuffer, StopsAtTheSizeLimit) {
    const std::string big(1 << 20, 'a');
    expectReadError([&] { gunzipBuffer(gzipBuffer(big), 1000); }, "", "more than 1000 bytes");
    EXPECT_EQ(gunzipBuffer(gzipBuffer(big), big.size()).size(), big.size());
}

TEST(GzipCloudFile, EveryFormatRoundTripsExactly) {
    const std::string dir = scratchDir("GzipCloudFile", "roundtrip");
    const PointCloud cloud = randomCloud(3000, 11);
    for (const char* name : {"c.pcd.gz", "c.ply.gz", "c.xyz.gz", "C.PCD.GZ"}) {
        SCOPED_TRACE(name);
        const std::string path = dir + "/" + name;
        writeCloudFile(path, cloud);
        const std::string bytes = readBytes(path);
        ASSERT_GE(bytes.size(), 2u);
        EXPECT_EQ(static_cast<unsigned char>(bytes[0]), 0x1f);  // really gzipped
        EXPECT_EQ(readCloudFile(path), cloud);
    }
    // The gzipped PCD inflates to exactly the plain binary PCD (what other tools read).
    writeCloudFile(dir + "/plain.pcd", cloud);
    EXPECT_EQ(gunzipBuffer(readBytes(dir + "/c.pcd.gz")), readBytes(dir + "/plain.pcd"));
}

TEST(GzipCloudFile, BadCompressedFilesNameThePathAndTheProblem) {
    const std::string dir = scratchDir("GzipCloudFile", "bad");
    const std::string pcd = plainPcd(randomCloud(100, 5));
    const std::string gz = gzipBuffer(pcd);
    auto expectFileError = [&](const std::string& name, const std::string& bytes, const std::string& phrase) {
        SCOPED_TRACE(name);
        const std::string path = dir + "/" + name;
        writeRaw(path, bytes);
        expectReadError([&] { readCloudFile(path); }, path + ": ", phrase);
    };
    expectFileError("plain.pcd.gz", pcd, "not gzip data");
    expectFileError("cut.pcd.gz", gz.substr(0, gz.size() / 3), "truncated gzip data");
    // Inflated while parsed: the container's end is checked once the cloud is read (a PLY reader
    // would stop earlier, at the PCD header inside).
    expectFileError("junk.pcd.gz", gz + "xx", "trailing data");
    // Valid gzip around a broken cloud: the inner format's error, still with the path.
    expectFileError("badpcd.pcd.gz", gzipBuffer(pcd.substr(0, pcd.size() - 7)), "truncated binary data");
    expectFileError("text.xyz.gz", gzipBuffer("1 2 3\n1 two 3\n"), "'two' is not a number");
    expectFileError("nan.xyz.gz", gzipBuffer("nan 0 0\n"), "contains no finite points");
    expectFileError("empty.pcd.gz", "", "file is empty");
}

TEST(GzipCloudFile, RandomCorruptionNeverCrashes) {
    const std::string dir = scratchDir("GzipCloudFile", "fuzz");
    const std::string gz = gzipBuffer(plainPcd(randomCloud(300, 6)));
    std::mt19937 rng(99);
    for (int trial = 0; trial < 60; ++trial) {
        std::string bytes = gz;
        const std::size_t at = std::uniform_int_distribution<std::size_t>(0, bytes.size() - 1)(rng);
        bytes[at] = static_cast<char>(bytes[at] ^ (1 + trial % 255));
        const std::string path = dir + "/f.pcd.gz";
        writeRaw(path, bytes);
        try {
            readCloudFile(path);  // a flip in an unused header bit may still read fine
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
        }
    }
}

}  // namespace
}  // namespace stairmap::io
