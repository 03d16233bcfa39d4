// Our Velodyne packet decoder: synthetic packets with known geometry (VLP-16, HDL-32E, dual
// return, range filter, damaged blocks).
#include <gtest/gtest.h>

#include <cmath>

#include "VelodyneTestUtil.h"
#include "io/rawlog/VelodyneDecoder.h"

using namespace stairmap;
using namespace stairmap::io;
using namespace stairmap::test;

namespace {

constexpr double kDeg = M_PI / 180.0;

// Datasheet beam model, written out independently of the decoder: azimuth clockwise from x.
Eigen::Vector3d expectedPoint(double range_m, double elevation_deg, double azimuth_deg,
                              double vertical_offset_m) {
    const double xy = range_m * std::cos(elevation_deg * kDeg);
    return {xy * std::cos(azimuth_deg * kDeg), -xy * std::sin(azimuth_deg * kDeg),
            range_m * std::sin(elevation_deg * kDeg) + vertical_offset_m};
}

PointCloud decodeOne(const std::vector<std::uint8_t>& packet, VelodyneModel model,
                     VelodyneDecodeStats* stats = nullptr, VelodyneDecoderParams params = {}) {
    return decodeVelodynePackets(packet.data(), 1, defaultVelodyneCalibration(model), params, stats);
}

void expectNear(const Eigen::Vector3f& got, const Eigen::Vector3d& want, double tol = 1e-4) {
    EXPECT_LT((got.cast<double>() - want).norm(), tol) << "got " << got.transpose() << " want "
                                                      << want.transpose();
}

}  // namespace

TEST(VelodyneDecoder, Vlp16BothFiringSequencesWithInterpolatedAzimuth) {
    auto p = makeVelodynePacket(9000, 20, 0x37, 0x22);  // blocks at 90.00, 90.20, ... deg
    setReturn(p, 3, 0, 5000);   // block 3, sequence 0, laser 0 (-15 deg): 10 m at 90.60 deg
    setReturn(p, 3, 21, 2500);  // block 3, sequence 1, laser 5 (+5 deg): 5 m
    setReturn(p, 11, 16, 1000); // last block, sequence 1, laser 0: gap taken from block 10 -> 11
    VelodyneDecodeStats stats;
    const PointCloud pts = decodeOne(p, VelodyneModel::VLP16, &stats);
    ASSERT_EQ(pts.size(), 3u);
    EXPECT_EQ(stats.valid_returns, 3u);
    expectNear(pts[0], expectedPoint(10.0, -15, 90.60, 0.0112));
    // Sequence 1, laser 5 fires (55.296 + 5 * 2.304) us into a 110.592 us block of 0.20 deg.
    const double frac = (55.296 + 5 * 2.304) / 110.592;
    expectNear(pts[1], expectedPoint(5.0, 5, 90.60 + 0.20 * frac, -0.0037));
    expectNear(pts[2], expectedPoint(2.0, -15, 92.20 + 0.10, 0.0112));
}

TEST(VelodyneDecoder, AzimuthWrapsAt360) {
    auto p = makeVelodynePacket(35990, 20, 0x37, 0x22);  // block 1 at 0.10 deg
    setReturn(p, 0, 16, 5000);  // second sequence of block 0: 359.90 + 0.10 = 360.00 deg
    const PointCloud pts = decodeOne(p, VelodyneModel::VLP16);
    ASSERT_EQ(pts.size(), 1u);
    expectNear(pts[0], expectedPoint(10.0, -15, 0.0, 0.0112));
}

TEST(VelodyneDecoder, Hdl32AllThirtyTwoLasers) {
    auto p = makeVelodynePacket(0, 16, 0x37, 0x21);
    for (int ch = 0; ch < 32; ++ch) setReturn(p, 0, ch, 2500);  // 5 m on every laser
    EXPECT_EQ(velodyneModelFromPacket(p.data(), VelodyneModel::VLP16), VelodyneModel::HDL32);
    const PointCloud pts = decodeOne(p, VelodyneModel::HDL32);
    ASSERT_EQ(pts.size(), 32u);
    // HDL-32E datasheet: laser 15 is horizontal, laser 31 at +10.67, laser 0 at -30.67 deg.
    expectNear(pts[0], expectedPoint(5.0, -30.67, 0.0, 0.0));
    expectNear(pts[15], expectedPoint(5.0, 0.0, 0.16 * 15 * 1.152 / 46.08, 0.0));
    expectNear(pts[31], expectedPoint(5.0, 10.67, 0.16 * 31 * 1.152 / 46.08, 0.0));
    int upward = 0;
    for (const auto& q : pts) upward += q.z() > 0 ? 1 : 0;
    EXPECT_EQ(upward, 8);  // lasers 17, 19, ..., 31
}

TEST(VelodyneDecoder, DualReturnKeepsBothReturns) {
    auto p = makeVelodynePacket(0, 0, 0x39, 0x22);
    for (int b = 0; b < 12; ++b) {  // pairs of blocks share an azimuth: 0, 0, 0.4, 0.4, ...
        const int az = 40 * (b / 2);
        p[b * 100 + 2] = std::uint8_t(az & 0xFF);
        p[b * 100 + 3] = std::uint8_t(az >> 8);
        setReturn(p, b, 16, b % 2 == 0 ? 5000 : 4000);  // strongest 10 m, last 8 m
    }
    const PointCloud pts = decodeOne(p, VelodyneModel::VLP16);
    ASSERT_EQ(pts.size(), 12u);
    // Second firing of block pair 0 lies halfway to the next pair (0.4 deg apart).
    expectNear(pts[0], expectedPoint(10.0, -15, 0.20, 0.0112));
    expectNear(pts[1], expectedPoint(8.0, -15, 0.20, 0.0112));
    expectNear(pts[11], expectedPoint(8.0, -15, 2.00 + 0.20, 0.0112));
}

TEST(VelodyneDecoder, RangeFilterAndDamagedBlocks) {
    auto p = makeVelodynePacket(0, 20, 0x37, 0x22);
    setReturn(p, 0, 0, 100);    // 0.2 m: too close
    setReturn(p, 0, 1, 65000);  // 130 m: too far for max 100 m
    setReturn(p, 0, 2, 1000);   // 2 m: kept
    setReturn(p, 5, 0, 1000);
    p[5 * 100] = 0x00;  // damage block 5's flag
    VelodyneDecodeStats stats;
    VelodyneDecoderParams params;
    params.min_range_m = 1.0f;
    params.max_range_m = 100.0f;
    const PointCloud pts = decodeOne(p, VelodyneModel::VLP16, &stats, params);
    EXPECT_EQ(pts.size(), 1u);
    EXPECT_EQ(stats.valid_returns, 3u);
    EXPECT_EQ(stats.range_filtered, 2u);
    EXPECT_EQ(stats.bad_blocks, 1u);
    EXPECT_EQ(stats.packets, 1u);
}

TEST(VelodyneDecoder, EmptyPacketListGivesEmptyCloud) {
    VelodyneDecodeStats stats;
    const PointCloud pts = decodeVelodynePackets(nullptr, 0, defaultVelodyneCalibration(VelodyneModel::VLP16), {}, &stats);
    EXPECT_TRUE(pts.empty());
    EXPECT_EQ(stats.packets, 0u);
}
