// Our Velodyne decoding on real captures: the VLP-16 pcap (UDP payloads), the same 3 rotations
// stored in a rawlog, an HDL-32E rawlog and another VLP-16 rawlog. Checks that every valid return
// in range becomes a point, and that where MRPT 2.5.8's generatePointCloud() decodes the same
// return the two agree. MRPT decodes only half of each block (VLP-16: the first firing sequence;
// HDL-32E: channels 0-15), which is why stairmap decodes packets itself; counts are printed.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/serialization/CArchive.h>

#include <cstring>
#include <iostream>

#include "VelodyneTestUtil.h"
#include "io/rawlog/ObservationToPoints.h"
#include "io/rawlog/VelodyneDecoder.h"

using namespace stairmap;
using namespace stairmap::io;
using namespace stairmap::test;
using mrpt::obs::CObservationVelodyneScan;

namespace {

const std::string kRealDir = std::string(STAIRMAP_SHARED_DIR) + "/data/real/";

std::vector<CObservationVelodyneScan::Ptr> readVelodyneRawlog(const std::string& name) {
    mrpt::io::CFileGZInputStream f(kRealDir + name);
    auto ar = mrpt::serialization::archiveFrom(f);
    std::vector<CObservationVelodyneScan::Ptr> out;
    for (;;) {
        const uint64_t before = f.getPosition();
        try {
            auto obj = ar.ReadObject();
            if (auto v = std::dynamic_pointer_cast<CObservationVelodyneScan>(obj)) out.push_back(v);
        } catch (const std::exception&) {
            EXPECT_EQ(f.getPosition(), before) << name << " should end cleanly";
            break;
        }
    }
    return out;
}

std::size_t validReturns(const CObservationVelodyneScan& v, double min_m, double max_m) {
    std::size_t n = 0;
    for (const auto& pkt : v.scan_packets) {
        n += countValidReturns(reinterpret_cast<const std::uint8_t*>(&pkt), min_m, max_m);
    }
    return n;
}

struct Agreement {
    std::size_t mrpt_points = 0, ours = 0, valid = 0, matched = 0;
    double mean_m = 0, max_m = 0;
    double max_angle_rad = 0;  ///< max distance / range: angular disagreement
};

// Our decoding (through the observation conversion, sensor frame recovered by removing the
// sensor pose) against MRPT's generatePointCloud() on the same observation.
Agreement compareWithMrpt(CObservationVelodyneScan& v) {
    Agreement a;
    const ObservationPoints ours = observationToRobotPoints(v);  // min range 1 m as MRPT's default
    PointCloud ours_sensor;
    const Eigen::Vector3f offset(float(v.sensorPose.x()), float(v.sensorPose.y()), float(v.sensorPose.z()));
    for (const auto& p : ours.points_robot) ours_sensor.push_back(p - offset);  // pure translation here
    v.generatePointCloud();
    a.mrpt_points = v.point_cloud.size();
    a.ours = ours_sensor.size();
    a.valid = validReturns(v, std::max(1.0, v.minRange), v.maxRange);
    const NearestNeighbour nn(ours_sensor, 0.05f);
    for (std::size_t i = 0; i < a.mrpt_points; ++i) {
        const Eigen::Vector3f q(v.point_cloud.x[i], v.point_cloud.y[i], v.point_cloud.z[i]);
        const float d = nn.distance(q);
        if (!std::isfinite(d)) continue;
        a.max_angle_rad = std::max<double>(a.max_angle_rad, d / q.norm());
        ++a.matched;
        a.mean_m += d;
        a.max_m = std::max<double>(a.max_m, d);
    }
    if (a.matched) a.mean_m /= double(a.matched);
    return a;
}

void print(const std::string& name, std::size_t k, const Agreement& a) {
    std::cout << name << " scan " << k << ": valid returns in range " << a.valid << ", ours "
              << a.ours << ", MRPT generatePointCloud " << a.mrpt_points << ", MRPT points matched "
              << a.matched << ", mean/max distance " << a.mean_m * 1e3 << "/" << a.max_m * 1e3
              << " mm, max angle " << a.max_angle_rad * 180 / M_PI << " deg\n";
}

}  // namespace

TEST(VelodyneRealData, PcapEveryValidReturnDecoded) {
    const auto packets = readPcapUdpPayloads(kRealDir + "sample_velodyne_vlp16_gps.pcap", 2368, 1206);
    ASSERT_EQ(packets.size(), 293u);  // the capture's data packets (plus 57 GPS packets on 8308)
    const auto calib = defaultVelodyneCalibration(VelodyneModel::VLP16);
    VelodyneDecoderParams params;
    params.min_range_m = 1.0f;
    params.max_range_m = 120.0f;
    std::size_t ours = 0, valid = 0, valid_any = 0;
    for (const auto& pkt : packets) {
        ASSERT_EQ(velodyneModelFromPacket(pkt.data(), VelodyneModel::HDL32), VelodyneModel::VLP16);
        PointCloud pts;
        VelodyneDecodeStats stats;
        decodeVelodynePacket(pkt.data(), calib, params, pts, stats);
        ours += pts.size();
        valid += countValidReturns(pkt.data(), 1.0, 120.0);
        valid_any += countValidReturns(pkt.data(), 1e-9, 1e9);
        for (const auto& p : pts) {
            ASSERT_TRUE(p.allFinite());
            ASSERT_LE(p.norm(), 120.1f);
        }
    }
    std::cout << "pcap: " << packets.size() << " data packets, valid returns " << valid_any
              << ", in [1, 120] m " << valid << ", ours " << ours << "\n";
    EXPECT_EQ(ours, valid);
    EXPECT_EQ(valid_any, 73486u);
}

TEST(VelodyneRealData, RawlogRotationsAreThePcapPackets) {
    const auto packets = readPcapUdpPayloads(kRealDir + "sample_velodyne_vlp16_gps.pcap", 2368, 1206);
    const auto scans = readVelodyneRawlog("sample_velodyne_vlp16_gps.rawlog");
    ASSERT_EQ(scans.size(), 3u);
    std::vector<const std::uint8_t*> rawlog_packets;
    for (const auto& s : scans) {
        for (const auto& pkt : s->scan_packets) rawlog_packets.push_back(reinterpret_cast<const std::uint8_t*>(&pkt));
    }
    ASSERT_EQ(rawlog_packets.size(), 226u);
    std::size_t start = 0;
    while (start < packets.size() && std::memcmp(packets[start].data(), rawlog_packets[0], 1206) != 0) ++start;
    EXPECT_EQ(start, 51u);  // the first full rotation of the capture (azimuth wraps at 51)
    ASSERT_LT(start + rawlog_packets.size(), packets.size() + 1);
    for (std::size_t i = 0; i < rawlog_packets.size(); ++i) {
        ASSERT_EQ(std::memcmp(packets[start + i].data(), rawlog_packets[i], 1206), 0) << i;
    }
}

TEST(VelodyneRealData, Vlp16RawlogMatchesMrptWhereBothDecode) {
    auto scans = readVelodyneRawlog("sample_velodyne_vlp16_gps.rawlog");
    ASSERT_EQ(scans.size(), 3u);
    for (std::size_t k = 0; k < scans.size(); ++k) {
        const Agreement a = compareWithMrpt(*scans[k]);
        print("sample_velodyne_vlp16_gps.rawlog", k, a);
        EXPECT_EQ(a.ours, a.valid);
        EXPECT_GE(a.ours, a.mrpt_points);
        EXPECT_EQ(a.matched, a.mrpt_points);  // every MRPT point has ours within 5 cm ...
        EXPECT_LT(a.max_m, 0.002);            // ... in fact within 2 mm
    }
}

TEST(VelodyneRealData, Hdl32RawlogMatchesMrptWhereBothDecode) {
    auto scans = readVelodyneRawlog("sample_velodyne_hdl32.rawlog");
    ASSERT_EQ(scans.size(), 2u);
    for (std::size_t k = 0; k < scans.size(); ++k) {
        const Agreement a = compareWithMrpt(*scans[k]);
        print("sample_velodyne_hdl32.rawlog", k, a);
        EXPECT_EQ(a.ours, a.valid);
        EXPECT_GE(a.ours, a.mrpt_points);
        EXPECT_EQ(a.matched, a.mrpt_points);
        // MRPT uses one azimuth per HDL-32E firing, we interpolate over its 46 us: up to 0.16 deg.
        EXPECT_LT(a.mean_m, 0.003);
        EXPECT_LT(a.max_m, 0.03);
    }
}

TEST(VelodyneRealData, Vlp16SecondRawlogWithSensorOffset) {
    auto scans = readVelodyneRawlog("test_velodyne_VLP16.rawlog");
    ASSERT_EQ(scans.size(), 1u);
    EXPECT_NEAR(scans[0]->sensorPose.z(), 0.09, 1e-6);
    const Agreement a = compareWithMrpt(*scans[0]);
    print("test_velodyne_VLP16.rawlog", 0, a);
    EXPECT_EQ(a.ours, a.valid);
    EXPECT_EQ(a.matched, a.mrpt_points);
    EXPECT_LT(a.mean_m, 0.002);
    // Outdoors up to ~100 m: MRPT's 0.01 deg azimuth tables give up to 2 cm there.
    EXPECT_LT(a.max_angle_rad, 0.03 * M_PI / 180);
}
