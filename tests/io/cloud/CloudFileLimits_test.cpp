// Memory limits of the cloud readers (docs/detect-io.md): gzip inflated while parsing within a
// budget, bounded text lines, declared counts checked against the bytes that follow the header
// before anything is allocated, and a cap on the points of one cloud.

#include <gtest/gtest.h>

#include <sstream>

#include "CloudFileTestUtil.h"
#include "io/cloud/CloudFile.h"
#include "io/cloud/GunzipStream.h"
#include "io/cloud/GzipBuffer.h"

namespace stairmap::io {
namespace {

using test::expectReadError;
using test::scratchDir;
using test::writeRaw;

const std::string kBinaryHeader = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\nPOINTS 2\nDATA binary\n";

/// Writes `bytes` to <scratch>/<file> and expects readCloudFile to fail saying `phrase`.
void expectFileError(const std::string& file, const std::string& bytes, const std::string& phrase) {
    const std::string path = scratchDir("CloudFileLimits", "f") + "/" + file;
    writeRaw(path, bytes);
    expectReadError([&] { readCloudFile(path); }, path + ": ", phrase);
}

TEST(GunzipStream, InflatesOnDemandAndStopsAtTheBudget) {
    std::string data;
    for (int i = 0; i < 20000; ++i) data += "0.25 -1 2\n";
    std::istringstream source(gzipBuffer(data));
    GunzipStream in(source, data.size());
    std::string line;
    ASSERT_TRUE(std::getline(in, line));
    EXPECT_EQ(line, "0.25 -1 2");
    in.finish();  // the rest inflates cleanly within the budget
    EXPECT_TRUE(in.error().empty());

    std::istringstream again(gzipBuffer(data));
    GunzipStream small(again, data.size() - 1);
    std::string all((std::istreambuf_iterator<char>(small)), std::istreambuf_iterator<char>());
    EXPECT_LT(all.size(), data.size());  // the stream ended at the budget...
    EXPECT_NE(small.error().find("decompresses to more than"), std::string::npos);  // ...and says why
    EXPECT_THROW(small.finish(), std::runtime_error);
}

TEST(CloudFileLimits, GzipBombStopsAtTheDeclaredData) {
    // One declared point, then 64 MiB of zeros (compressing to 64 kB): the reader stops after the
    // point instead of inflating everything first.
    const std::string head = kBinaryHeader + std::string(24, '\0');
    const std::string bomb = gzipBuffer(head + std::string(std::size_t{64} << 20, '\0'), 1);
    expectFileError("bomb.pcd.gz", bomb, "data continues after the header's POINTS 2");
}

TEST(CloudFileLimits, GzipProblemsBehindAnEarlyEndAreReported) {
    // A stream cut short reads as "truncated gzip data", not as the reader's "truncated binary data".
    const std::string gz = gzipBuffer(kBinaryHeader + std::string(24, '\0'));
    expectFileError("cut.pcd.gz", gz.substr(0, gz.size() - 12), "truncated gzip data");
}

TEST(CloudFileLimits, TextLinesAreBounded) {
    const std::string long_line(kMaxCloudLineBytes + 10, '1');
    expectFileError("line.xyz", "1 2 3\n" + long_line + "\n", "line is longer than 1048576 bytes");
    expectFileError("header.pcd", "FIELDS " + long_line, "line is longer than");
    expectFileError("line.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                "property float z\nend_header\n" + long_line, "line is longer than");
    // Just under the limit is a normal (if odd) line: 3 numbers and padding blanks.
    const std::string path = scratchDir("CloudFileLimits", "ok") + "/ok.xyz";
    writeRaw(path, "1 2 3" + std::string(kMaxCloudLineBytes - 10, ' ') + "\n4 5 6\n");
    EXPECT_EQ(readCloudFile(path).size(), 2u);
}

TEST(CloudFileLimits, DeclaredBinaryDataMustFitInTheFile) {
    // 4 million declared points (48 MB) in a file of a few bytes: refused before any allocation.
    expectFileError("many.pcd",
                    "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 4000000\nPOINTS 4000000\nDATA binary\n" +
                        std::string(36, '\0'),
                    "header declares 4000000 points of 12 bytes, the file holds 36 bytes");
    expectFileError("many.ply",
                    "ply\nformat binary_little_endian 1.0\nelement vertex 4000000\nproperty float x\n"
                    "property float y\nproperty float z\nend_header\n" + std::string(36, '\0'),
                    "element 'vertex' declares 4000000 entries of 12 bytes, the file holds 36 bytes");
}

TEST(CloudFileLimits, PointRecordsAndCountsAreBounded) {
    expectFileError("record.pcd",
                    "FIELDS x y z h g\nSIZE 4 4 4 8 8\nTYPE F F F F F\nCOUNT 1 1 1 100000 100000\nWIDTH 1\n"
                    "POINTS 1\nDATA binary\n",
                    "point record is larger than 1048576 bytes");
    const std::string over = std::to_string(kMaxCloudPoints + 1);
    expectFileError("count.pcd",
                    "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH " + over + "\nPOINTS " + over + "\nDATA ascii\n",
                    "more than the limit of 4000000 points");
}

TEST(CloudFileLimits, CloudsWithoutADeclaredCountStopAtThePointLimit) {
    // XYZ declares nothing: the reader counts. 4M + 1 points compress to 24 kB.
    std::string data;
    data.reserve((kMaxCloudPoints + 1) * 6);
    for (std::size_t i = 0; i <= kMaxCloudPoints; ++i) data += "0 0 0\n";
    expectFileError("many.xyz.gz", gzipBuffer(data, 1), "more than 4000000 points");
}

}  // namespace
}  // namespace stairmap::io
