// PointCloud2 layouts a ROS 2 driver may send, built byte by byte here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "ros2/PointCloudDecoder.h"

namespace stairmap::ros2 {
namespace {

/// Writes float v at byte `offset` of `data`, big-endian if asked.
void putFloat(std::vector<std::uint8_t>& data, std::size_t offset, float v, bool big_endian = false) {
    std::uint8_t b[4];
    std::memcpy(b, &v, 4);
    for (int i = 0; i < 4; ++i) data[offset + i] = big_endian ? b[3 - i] : b[i];
}

CloudLayout xyzLayout(std::uint32_t width, std::uint32_t point_step, std::uint32_t height = 1) {
    CloudLayout layout;
    layout.width = width;
    layout.height = height;
    layout.point_step = point_step;
    layout.row_step = width * point_step;
    layout.fields = {{"x", 0, kFloat32, 1}, {"y", 4, kFloat32, 1}, {"z", 8, kFloat32, 1}};
    return layout;
}

TEST(PointCloudDecoder, PlainXyz) {
    const CloudLayout layout = xyzLayout(2, 12);
    std::vector<std::uint8_t> data(24);
    const float values[] = {1, 2, 3, -4, -5, 6.5f};
    for (int i = 0; i < 6; ++i) putFloat(data, 4 * i, values[i]);
    const CloudDecodeResult r = decodePointCloud(layout, data.data(), data.size());
    ASSERT_EQ(r.status, CloudDecodeStatus::Ok) << r.problem;
    ASSERT_EQ(r.points.size(), 2u);
    EXPECT_EQ(r.points[1], Eigen::Vector3f(-4, -5, 6.5f));
}

TEST(PointCloudDecoder, XyziWithPaddingAndFieldsInAnyOrder) {
    // Velodyne-style: x y z at 0/4/8, padding, intensity at 16, ring at 20, point_step 32
    CloudLayout layout;
    layout.width = 3;
    layout.point_step = 32;
    layout.row_step = 96;
    layout.fields = {{"intensity", 16, kFloat32, 1}, {"ring", 20, kUint16, 1},
                     {"z", 8, kFloat32, 1}, {"y", 4, kFloat32, 1}, {"x", 0, kFloat32, 1}};
    std::vector<std::uint8_t> data(96, 0xAB);  // garbage in the padding
    for (int p = 0; p < 3; ++p) {
        putFloat(data, 32 * p + 0, 10.0f + p);
        putFloat(data, 32 * p + 4, 20.0f + p);
        putFloat(data, 32 * p + 8, 30.0f + p);
        putFloat(data, 32 * p + 16, 99.0f);
    }
    const CloudDecodeResult r = decodePointCloud(layout, data.data(), data.size());
    ASSERT_EQ(r.status, CloudDecodeStatus::Ok) << r.problem;
    ASSERT_EQ(r.points.size(), 3u);
    EXPECT_EQ(r.points[2], Eigen::Vector3f(12, 22, 32));
}

TEST(PointCloudDecoder, OrganisedWithNansAndRowPadding) {
    // 2 rows x 3 columns, 4 bytes of padding at the end of each row, two NaN points
    CloudLayout layout = xyzLayout(3, 16, 2);
    layout.row_step = 3 * 16 + 4;
    std::vector<std::uint8_t> data(2 * layout.row_step, 0);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (int row = 0; row < 2; ++row)
        for (int col = 0; col < 3; ++col) {
            const std::size_t at = row * layout.row_step + col * 16;
            const bool hole = (row == 0 && col == 1) || (row == 1 && col == 2);
            putFloat(data, at, hole ? nan : float(row));
            putFloat(data, at + 4, float(col));
            putFloat(data, at + 8, 1.0f);
        }
    const CloudDecodeResult r = decodePointCloud(layout, data.data(), data.size());
    ASSERT_EQ(r.status, CloudDecodeStatus::Ok) << r.problem;
    EXPECT_EQ(r.points.size(), 4u);
    EXPECT_EQ(r.dropped_non_finite, 2u);
    EXPECT_EQ(r.points[2], Eigen::Vector3f(1, 0, 1));  // row 1, col 0
}

TEST(PointCloudDecoder, BigEndianIsSwapped) {
    CloudLayout layout = xyzLayout(1, 12);
    layout.is_bigendian = true;
    std::vector<std::uint8_t> data(12);
    putFloat(data, 0, 1.5f, true);
    putFloat(data, 4, -2.0f, true);
    putFloat(data, 8, 0.75f, true);
    const CloudDecodeResult r = decodePointCloud(layout, data.data(), data.size());
    ASSERT_EQ(r.status, CloudDecodeStatus::Ok) << r.problem;
    EXPECT_EQ(r.points.at(0), Eigen::Vector3f(1.5f, -2.0f, 0.75f));
}

TEST(PointCloudDecoder, Float64Coordinates) {
    CloudLayout layout;
    layout.width = 1;
    layout.point_step = 24;
    layout.row_step = 24;
    layout.fields = {{"x", 0, kFloat64, 1}, {"y", 8, kFloat64, 1}, {"z", 16, kFloat64, 1}};
    const double xyz[3] = {0.5, 1.5, -2.5};
    std::vector<std::uint8_t> data(24);
    std::memcpy(data.data(), xyz, 24);
    const CloudDecodeResult r = decodePointCloud(layout, data.data(), data.size());
    ASSERT_EQ(r.status, CloudDecodeStatus::Ok) << r.problem;
    EXPECT_EQ(r.points.at(0), Eigen::Vector3f(0.5f, 1.5f, -2.5f));
}

TEST(PointCloudDecoder, MissingOrWrongFieldsAreNoXyz) {
    std::vector<std::uint8_t> data(24, 0);
    CloudLayout no_z = xyzLayout(2, 12);
    no_z.fields.pop_back();
    EXPECT_EQ(decodePointCloud(no_z, data.data(), data.size()).status, CloudDecodeStatus::NoXyz);
    CloudLayout int_x = xyzLayout(2, 12);
    int_x.fields[0].datatype = kInt32;
    EXPECT_EQ(decodePointCloud(int_x, data.data(), data.size()).status, CloudDecodeStatus::NoXyz);
    CloudLayout outside = xyzLayout(2, 12);
    outside.fields[2].offset = 10;  // z would end at byte 14 of a 12-byte point
    const CloudDecodeResult r = decodePointCloud(outside, data.data(), data.size());
    EXPECT_EQ(r.status, CloudDecodeStatus::NoXyz);
    EXPECT_NE(r.problem.find("point_step"), std::string::npos) << r.problem;
}

TEST(PointCloudDecoder, TruncatedAndAbsurdSizesAreMalformed) {
    std::vector<std::uint8_t> data(24, 0);
    const CloudDecodeResult truncated = decodePointCloud(xyzLayout(3, 12), data.data(), data.size());
    EXPECT_EQ(truncated.status, CloudDecodeStatus::Malformed);
    EXPECT_NE(truncated.problem.find("24 bytes"), std::string::npos) << truncated.problem;
    CloudLayout huge = xyzLayout(0xFFFFFFFFu, 12, 0xFFFFFFFFu);
    huge.row_step = 12;  // overflowing products must not wrap around into "fits"
    EXPECT_EQ(decodePointCloud(huge, data.data(), data.size()).status, CloudDecodeStatus::Malformed);
    CloudLayout short_rows = xyzLayout(2, 12);
    short_rows.row_step = 12;
    EXPECT_EQ(decodePointCloud(short_rows, data.data(), data.size()).status, CloudDecodeStatus::Malformed);
    CloudLayout big = xyzLayout(70000, 12, 100);  // 7 M points > the 4 M limit, before any data check
    EXPECT_EQ(decodePointCloud(big, data.data(), data.size()).status, CloudDecodeStatus::Malformed);
    EXPECT_EQ(decodePointCloud(xyzLayout(2, 12), nullptr, 0).status, CloudDecodeStatus::Malformed);
}

TEST(PointCloudDecoder, EmptyCloudIsValid) {
    const CloudDecodeResult r = decodePointCloud(xyzLayout(0, 12), nullptr, 0);
    EXPECT_EQ(r.status, CloudDecodeStatus::Ok) << r.problem;
    EXPECT_TRUE(r.points.empty());
}

}  // namespace
}  // namespace stairmap::ros2
