// `--sensor` on the bundled VLP-16 capture: MRPT's CVelodyneScanner replays the pcap, stairmap's
// decoder turns each rotation into a scan. The scans must be the ones stairmap's decoder makes from
// the rawlog of the same packets (same points, bit for bit), and the count of every rotation must
// equal the valid returns counted straight from the packet bytes.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/serialization/CArchive.h>

#include <iostream>
#include <thread>

#include "SensorTestUtil.h"
#include "io/rawlog/ObservationToPoints.h"
#include "io/rawlog/VelodyneTestUtil.h"
#include "sensors/SensorSource.h"

using namespace stairmap;
using namespace stairmap::test;

namespace {

/// stairmap's decoding of every Velodyne rotation stored in the rawlog.
std::vector<PointCloud> rawlogScans() {
    mrpt::io::CFileGZInputStream f(kRawlog);
    auto archive = mrpt::serialization::archiveFrom(f);
    std::vector<PointCloud> out;
    for (;;) {
        mrpt::serialization::CSerializable::Ptr object;
        try {
            object = archive.ReadObject();
        } catch (const std::exception&) {
            break;  // end of file
        }
        if (auto v = std::dynamic_pointer_cast<mrpt::obs::CObservationVelodyneScan>(object)) {
            out.push_back(io::observationToRobotPoints(*v).points_robot);
        }
    }
    return out;
}

/// Valid returns in [1, 120] m per rotation of the capture, rotations split where the packet's
/// first azimuth goes down (the azimuth wraps); the last, unfinished rotation is left out.
std::vector<std::size_t> validReturnsPerRotation() {
    const auto packets = readPcapUdpPayloads(kPcap, 2368, 1206);
    std::vector<std::size_t> counts(1, 0);
    int last_azimuth = -1;
    for (const auto& p : packets) {
        const int azimuth = p[2] | p[3] << 8;  // block 0
        if (azimuth < last_azimuth) counts.push_back(0);
        last_azimuth = azimuth;
        counts.back() += countValidReturns(p.data(), 1.0, 120.0);
    }
    counts.pop_back();
    return counts;
}

struct Replay {
    CollectingSink sink;
    std::map<std::string, std::size_t> counters;
    double seconds = 0;
};

void replay(const std::string& name, bool fast, Replay& r) {
    const std::string ini = writeFile(tempDir(name) + "/vlp16.ini", velodyneIni(kPcap, fast));
    sensors::SensorSourceOptions options;
    options.static_robot = true;
    auto source = sensors::makeSensorSource(ini, options);
    EXPECT_TRUE(source->lossy());
    std::atomic<bool> stop{false};
    const auto t0 = std::chrono::steady_clock::now();
    source->run(r.sink, stop);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.counters = source->counters();
}

}  // namespace

TEST(SensorSourcePcap, SameScansAsTheRawlogOfTheSamePackets) {
    Replay r;
    replay("same_scans", true, r);
    const std::vector<PointCloud> expected = rawlogScans();
    ASSERT_EQ(expected.size(), 3u);
    const std::vector<std::size_t> valid = validReturnsPerRotation();
    ASSERT_EQ(valid.size(), 4u);  // a partial first rotation, then the rawlog's 3
    ASSERT_EQ(r.sink.scans.size(), 4u);
    for (std::size_t k = 0; k < 4; ++k) {
        const Scan& s = r.sink.scans[k];
        std::cout << "rotation " << k << ": pcap replay " << s.points_robot.size() << " points, valid returns "
                  << valid[k];
        if (k > 0) std::cout << ", rawlog " << expected[k - 1].size();
        std::cout << "\n";
        EXPECT_EQ(s.points_robot.size(), valid[k]) << k;
        EXPECT_EQ(s.index, k);
        EXPECT_EQ(s.sensor_label, "lidar_SCAN");
        EXPECT_TRUE(s.T_world_robot.isApprox(Eigen::Isometry3d::Identity()));
        if (k == 0) continue;
        ASSERT_EQ(s.points_robot.size(), expected[k - 1].size()) << k;
        for (std::size_t i = 0; i < s.points_robot.size(); ++i) {
            ASSERT_EQ(s.points_robot[i], expected[k - 1][i]) << "rotation " << k << " point " << i;
        }
    }
    EXPECT_EQ(r.counters.at("scans"), 4u);
    EXPECT_EQ(r.counters.at("scans_pushed"), 4u);
    EXPECT_EQ(r.counters.at("bad_observations"), 0u);
    EXPECT_EQ(r.counters.at("scans_without_pose"), 0u);
    EXPECT_GT(r.counters.at("other_observations"), 0u);  // GPS packets, decimated by the driver
    std::size_t points = 0;
    for (const auto& s : r.sink.scans) points += s.points_robot.size();
    EXPECT_EQ(r.counters.at("points_pushed"), points);
    const double span = r.sink.times_s.back() - r.sink.times_s.front();
    std::cout << "fast replay: " << r.sink.scans.size() << " scans in " << r.seconds << " s (the driver waits 250 ms "
              << "at the end of the file); " << 3.0 / span << " scans/s between the first and the last\n";
}

TEST(SensorSourcePcap, RecordedRateReplayIsPacedAndStampsIncrease) {
    Replay r;
    replay("recorded_rate", false, r);
    ASSERT_EQ(r.sink.scans.size(), 4u);
    // The driver waits 100 ms after each completed rotation (pcap_read_full_scan_delay_ms).
    EXPECT_GE(r.seconds, 0.35);
    for (std::size_t k = 1; k < 4; ++k) {
        EXPECT_GE(r.sink.times_s[k] - r.sink.times_s[k - 1], 0.08) << k;
        EXPECT_GT(r.sink.scans[k].stamp_s, r.sink.scans[k - 1].stamp_s) << k;  // arrival stamps
    }
    const double span = r.sink.times_s.back() - r.sink.times_s.front();
    std::cout << "recorded-rate replay: " << r.sink.scans.size() << " scans in " << r.seconds
              << " s; " << 3.0 / span << " scans/s between the first and the last\n";
}

TEST(SensorSourcePcap, StopsSoonAfterTheStopFlagOnALoopedReplay) {
    const std::string dir = tempDir("stop");
    std::string text = velodyneIni(kPcap, false);
    text.replace(text.find("pcap_read_once = true"), 21, "pcap_read_once = false");
    const std::string ini = writeFile(dir + "/looped.ini", text);
    sensors::SensorSourceOptions options;
    options.static_robot = true;
    auto source = sensors::makeSensorSource(ini, options);
    CollectingSink sink;
    std::atomic<bool> stop{false};
    std::thread runner([&] { source->run(sink, stop); });
    std::this_thread::sleep_for(std::chrono::milliseconds(1200));  // loops the 0.4 s file
    const auto t_stop = std::chrono::steady_clock::now();
    stop = true;
    runner.join();
    const double latency = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_stop).count();
    std::cout << "stop latency " << latency * 1e3 << " ms after " << sink.scans.size() << " scans\n";
    EXPECT_GT(sink.scans.size(), 4u);  // the file was replayed more than once
    EXPECT_LT(latency, 0.5);
}

// The example shipped in config/ opens from any working directory (pcap path relative to the INI).
TEST(SensorSourcePcap, ShippedExampleIni) {
    sensors::SensorSourceOptions options;
    options.static_robot = true;
    auto source = sensors::makeSensorSource(std::string(STAIRMAP_SOURCE_DIR) + "/config/sensors/vlp16_pcap.ini", options);
    EXPECT_NE(source->describe().find("sample_velodyne_vlp16_gps.pcap"), std::string::npos) << source->describe();
    CollectingSink sink;
    std::atomic<bool> stop{false};
    source->run(sink, stop);
    EXPECT_EQ(sink.scans.size(), 4u);
}

// [sensor] label_filter: "lidar" matches MRPT's "lidar_SCAN"; another label skips every scan.
TEST(SensorSourcePcap, LabelFilter) {
    const std::string ini = writeFile(tempDir("label") + "/vlp16.ini", velodyneIni(kPcap, true));
    for (const std::string label : {"lidar", "lidar_SCAN", "other"}) {
        sensors::SensorSourceOptions options;
        options.static_robot = true;
        options.sensor_label = label;
        auto source = sensors::makeSensorSource(ini, options);
        CollectingSink sink;
        std::atomic<bool> stop{false};
        source->run(sink, stop);
        const bool match = label != "other";
        EXPECT_EQ(sink.scans.size(), match ? 4u : 0u) << label;
        EXPECT_EQ(source->counters().at("skipped_label"), match ? 0u : 4u) << label;
    }
}
