// Cloud files: round trips of every format and encoding, and hand-written files from other tools.

#include "io/cloud/CloudFile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "CloudFileTestUtil.h"

namespace stairmap::io {
namespace {

using test::bytesOf;
using test::randomCloud;
using test::scratchDir;
using test::writeRaw;

struct Variant {
    const char* extension;
    CloudFileEncoding encoding;
};

std::string variantName(const testing::TestParamInfo<Variant>& info) {
    return std::string(info.param.extension + 1) +
           (info.param.encoding == CloudFileEncoding::Ascii ? "Ascii" : "Binary");
}

class CloudFileRoundTrip : public testing::TestWithParam<Variant> {};

TEST_P(CloudFileRoundTrip, FileRoundTripIsExact) {
    const std::string dir = scratchDir("CloudFile", variantName({GetParam(), 0}));
    const std::string path = dir + "/cloud" + GetParam().extension;
    const PointCloud cloud = randomCloud(500, 7);
    writeCloudFile(path, cloud, GetParam().encoding);
    const PointCloud back = readCloudFile(path);
    ASSERT_EQ(back.size(), cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_EQ(back[i], cloud[i]) << "point " << i;
}

TEST_P(CloudFileRoundTrip, EmptyCloudRoundTripsToEmpty) {
    const std::string dir = scratchDir("CloudFile", "empty_" + variantName({GetParam(), 0}));
    const std::string path = dir + "/empty" + GetParam().extension;
    writeCloudFile(path, {}, GetParam().encoding);
    EXPECT_TRUE(readCloudFile(path).empty());
}

TEST_P(CloudFileRoundTrip, NonFinitePointsAreDroppedOnRead) {
    const std::string dir = scratchDir("CloudFile", "nonfinite_" + variantName({GetParam(), 0}));
    const std::string path = dir + "/mixed" + GetParam().extension;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const PointCloud cloud = {{1, 2, 3}, {nan, 0, 0}, {4, 5, 6}, {0, -inf, 0}, {0, 0, inf}, {7, 8, 9}};
    writeCloudFile(path, cloud, GetParam().encoding);
    const PointCloud back = readCloudFile(path);
    ASSERT_EQ(back.size(), 3u);
    EXPECT_EQ(back[0], Eigen::Vector3f(1, 2, 3));
    EXPECT_EQ(back[1], Eigen::Vector3f(4, 5, 6));
    EXPECT_EQ(back[2], Eigen::Vector3f(7, 8, 9));
}

INSTANTIATE_TEST_SUITE_P(AllFormats, CloudFileRoundTrip,
                         testing::Values(Variant{".xyz", CloudFileEncoding::Ascii},
                                         Variant{".pcd", CloudFileEncoding::Ascii},
                                         Variant{".pcd", CloudFileEncoding::Binary},
                                         Variant{".ply", CloudFileEncoding::Ascii},
                                         Variant{".ply", CloudFileEncoding::Binary}),
                         variantName);

TEST(CloudFile, StreamRoundTripsMatchFileRoundTrips) {
    const PointCloud cloud = randomCloud(50, 3);
    for (CloudFileEncoding enc : {CloudFileEncoding::Ascii, CloudFileEncoding::Binary}) {
        std::stringstream pcd, ply;
        writePcd(pcd, cloud, enc);
        writePly(ply, cloud, enc);
        EXPECT_EQ(readPcd(pcd), cloud);
        EXPECT_EQ(readPly(ply), cloud);
    }
    std::stringstream xyz;
    writeXyz(xyz, cloud);
    EXPECT_EQ(readXyz(xyz), cloud);
}

TEST(CloudFile, ExtensionIsCaseInsensitive) {
    const std::string path = scratchDir("CloudFile", "case") + "/CLOUD.PcD";
    writeCloudFile(path, {{1, 2, 3}});
    EXPECT_EQ(readCloudFile(path), PointCloud({{1, 2, 3}}));
}

TEST(CloudFile, XyzWithCommentsBlankLinesAndExtraColumns) {
    const std::string path = scratchDir("CloudFile", "xyz_hand") + "/hand.xyz";
    writeRaw(path, "# a comment line\n\n1 2 3 255 0 0\r\n  4.5\t-6e-1 +7 # trailing comment\n\n8 9 10\n");
    EXPECT_EQ(readCloudFile(path), PointCloud({{1, 2, 3}, {4.5f, -0.6f, 7}, {8, 9, 10}}));
}

TEST(CloudFile, AsciiPcdWithExtraFieldsOfEveryKind) {
    const std::string path = scratchDir("CloudFile", "pcd_extra_ascii") + "/extra.pcd";
    writeRaw(path,
             "# .PCD v0.7\nVERSION 0.7\nFIELDS intensity z normal x rgb y\nSIZE 2 8 4 4 4 4\n"
             "TYPE U F F F U F\nCOUNT 1 1 3 1 1 1\nWIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\n"
             "POINTS 2\nDATA ascii\n"
             "100 3.5 0 0 1 1.25 4278190080 2\n"
             "7 nan 0 1 0 9 0 9\n"
             "9 -1 0 1 0 -2 0 -3\n");
    // Three lines for POINTS 2: too many.
    test::expectReadError([&] { readCloudFile(path); }, path + ": ", "more point lines");
    writeRaw(path,
             "VERSION 0.7\nFIELDS intensity z normal x rgb y\nSIZE 2 8 4 4 4 4\n"
             "TYPE U F F F U F\nCOUNT 1 1 3 1 1 1\nWIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n"
             "100 3.5 0 0 1 1.25 4278190080 2\n"
             "7 nan 0 1 0 9 0 9\n"
             "9 -1 0 1 0 -2 0 -3\n");
    EXPECT_EQ(readCloudFile(path), PointCloud({{1.25f, 2, 3.5f}, {-2, -3, -1}}));
}

TEST(CloudFile, BinaryPcdWithExtraFieldsAndMixedTypes) {
    const std::string path = scratchDir("CloudFile", "pcd_extra_binary") + "/extra.pcd";
    std::string data =
        "VERSION 0.7\nFIELDS ring x label y z normal\nSIZE 2 8 1 4 2 4\nTYPE U F I F I F\n"
        "COUNT 1 1 1 1 1 3\nWIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2\nDATA binary\n";
    for (int i = 0; i < 2; ++i) {
        data += bytesOf<std::uint16_t>(15) + bytesOf<double>(0.5 + i) + bytesOf<std::int8_t>(-3) +
                bytesOf<float>(-1.5f * i) + bytesOf<std::int16_t>(static_cast<std::int16_t>(-2 + i)) +
                bytesOf<float>(0) + bytesOf<float>(0) + bytesOf<float>(1);
    }
    writeRaw(path, data);
    EXPECT_EQ(readCloudFile(path), PointCloud({{0.5f, 0, -2}, {1.5f, -1.5f, -1}}));
}

TEST(CloudFile, PcdOrganisedWithoutPointsLine) {
    const std::string path = scratchDir("CloudFile", "pcd_organised") + "/org.pcd";
    writeRaw(path, "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\nHEIGHT 2\nDATA ascii\n"
                   "1 0 0\nnan nan nan\n0 1 0\n0 0 1\n");
    EXPECT_EQ(readCloudFile(path), PointCloud({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}));
}

TEST(CloudFile, AsciiPlyWithDoubleCoordsColoursAndFaces) {
    const std::string path = scratchDir("CloudFile", "ply_ascii_hand") + "/mesh.ply";
    writeRaw(path,
             "ply\nformat ascii 1.0\ncomment made by hand\nobj_info test\n"
             "element camera 1\nproperty float view_x\nproperty list uchar int ids\n"
             "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
             "property uchar red\nproperty list uchar float extra\n"
             "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
             "0.5 2 7 8\n"
             "1.5 -2.25 3 255 0\n"
             "4 5 6 0 2 0.1 0.2\n"
             "-1e-3 0 1e2 9 1 3\n"
             "3 0 1 2\n");
    EXPECT_EQ(readCloudFile(path), PointCloud({{1.5f, -2.25f, 3}, {4, 5, 6}, {-1e-3f, 0, 100}}));
}

TEST(CloudFile, BinaryPlyWithDoubleCoordsAndFaceElements) {
    const std::string path = scratchDir("CloudFile", "ply_binary_hand") + "/mesh.ply";
    std::string data =
        "ply\nformat binary_little_endian 1.0\nelement material 2\nproperty list uchar short ids\n"
        "element vertex 2\nproperty uchar flags\nproperty double z\nproperty double y\n"
        "property double x\nproperty float intensity\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n";
    data += bytesOf<std::uint8_t>(2) + bytesOf<std::int16_t>(1) + bytesOf<std::int16_t>(2);  // material 0
    data += bytesOf<std::uint8_t>(0);                                                         // material 1
    data += bytesOf<std::uint8_t>(1) + bytesOf<double>(3) + bytesOf<double>(2) + bytesOf<double>(1) +
            bytesOf<float>(0.5f);
    data += bytesOf<std::uint8_t>(1) + bytesOf<double>(-3) + bytesOf<double>(-2) + bytesOf<double>(-1) +
            bytesOf<float>(0.5f);
    data += bytesOf<std::uint8_t>(3) + bytesOf<int>(0) + bytesOf<int>(1) + bytesOf<int>(0);
    writeRaw(path, data);
    EXPECT_EQ(readCloudFile(path), PointCloud({{1, 2, 3}, {-1, -2, -3}}));
}

TEST(CloudFile, BinaryPlyWithListPropertyInsideVertices) {
    const std::string path = scratchDir("CloudFile", "ply_binary_vertex_list") + "/lists.ply";
    std::string data =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty int x\n"
        "property list ushort float neighbours\nproperty float y\nproperty short z\nend_header\n";
    for (int i = 0; i < 3; ++i) {
        data += bytesOf<int>(10 * i) + bytesOf<std::uint16_t>(static_cast<std::uint16_t>(i));
        for (int k = 0; k < i; ++k) data += bytesOf<float>(99.0f);
        data += bytesOf<float>(0.5f * i) + bytesOf<std::int16_t>(static_cast<std::int16_t>(-i));
    }
    writeRaw(path, data);
    EXPECT_EQ(readCloudFile(path), PointCloud({{0, 0, 0}, {10, 0.5f, -1}, {20, 1, -2}}));
    writeRaw(path, data.substr(0, data.size() - 3));
    test::expectReadError([&] { readCloudFile(path); }, path + ": ", "file ends at entry 2");
}

TEST(CloudFile, WriterRejectsUnknownExtensionsAndUnwritablePaths) {
    const std::string dir = scratchDir("CloudFile", "write_errors");
    test::expectReadError([&] { writeCloudFile(dir + "/cloud.txt", {{1, 2, 3}}); }, dir + "/cloud.txt: ",
                          "cannot write");
    test::expectReadError([&] { writeCloudFile(dir + "/cloud.rawlog", {{1, 2, 3}}); }, dir + "/cloud.rawlog: ",
                          "cannot write");
    test::expectReadError([&] { writeCloudFile(dir + "/no/such/dir/c.pcd", {{1, 2, 3}}); },
                          dir + "/no/such/dir/c.pcd: ", "cannot be opened");
}

}  // namespace
}  // namespace stairmap::io
