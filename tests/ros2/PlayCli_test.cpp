// `stairmap play --ros2` as a separate process, received by a plain subscriber in this one:
// every scan of the rawlog arrives as a PointCloud2 with its points (in the sensor frame of the
// config) and an Odometry with its pose. Expected values come from reading the rawlog here.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "StairmapMessages.h"
#include "apps/ChildProcess.h"
#include "io/rawlog/RawlogScanSource.h"
#include "ros2/MessageBuilders.h"
#include "ros2/TestSubscriber.h"

namespace stairmap::ros2 {
namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;

const std::string kRawlog = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/sequences/ascending/seq_ascending.rawlog";
const std::string kPoses = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/sequences/ascending/poses.tum";

std::string scratch(const std::string& name) {
    const fs::path dir = fs::path(STAIRMAP_TEST_TMP) / ("ros2_play_" + std::to_string(getpid()));
    fs::create_directories(dir);
    return (dir / name).string();
}

TEST(PlayCli, EveryScanArrivesWithItsPointsAndPose) {
    io::RawlogScanSource expected_source(kRawlog, {}, io::TumTrajectory::load(kPoses));
    std::vector<Scan> expected;
    while (auto scan = expected_source.next()) expected.push_back(std::move(*scan));
    ASSERT_GE(expected.size(), 10u);

    const std::string prefix = "/playtest_" + std::to_string(getpid());
    test::TestSubscriber clouds(&sensor_msgs_msg_dds__PointCloud2__desc, ddsTopicName(prefix + "/points"));
    test::TestSubscriber odometry(&nav_msgs_msg_dds__Odometry__desc, ddsTopicName(prefix + "/odom"));
    const std::string config = scratch("mast.ini");
    std::ofstream(config) << "[sensor]\npose_z_m = 0.5\n";
    test::ChildOptions child;
    child.stderr_path = scratch("play.err");
    const pid_t pid = test::spawnStairmap({"play", kRawlog, "--poses", kPoses, "--config", config, "--ros2",
                                           "--rate", "20", "--points-topic", prefix + "/points",
                                           "--odom-topic", prefix + "/odom", "--wait-subscribers", "10"},
                                          child);
    std::vector<std::size_t> sizes;
    std::vector<Eigen::Vector3f> first_points;
    std::vector<double> stamps;
    const bool all = clouds.receive(
        [&](const void* s) {
            const auto& cloud = *static_cast<const sensor_msgs_msg_dds__PointCloud2_*>(s);
            const CloudDecodeResult r = decodePointCloud(cloudLayout(cloud), cloud.data._buffer, cloud.data._length);
            sizes.push_back(r.points.size());
            first_points.push_back(r.points.empty() ? Eigen::Vector3f::Zero() : r.points.front());
            stamps.push_back(headerStamp(cloud.header));
            EXPECT_STREQ(cloud.header.frame_id, "lidar");
        },
        [&] { return sizes.size() == expected.size(); }, 30s);
    EXPECT_EQ(test::waitForExit(pid, 30s), 0) << test::fileText(child.stderr_path);
    ASSERT_TRUE(all) << "received " << sizes.size() << " of " << expected.size() << " clouds";
    for (std::size_t k = 0; k < expected.size(); ++k) {
        EXPECT_EQ(sizes[k], expected[k].points_robot.size()) << "cloud " << k;
        EXPECT_NEAR(stamps[k], expected[k].stamp_s, 1e-6);
        // sensor frame = robot frame lowered by the 0.5 m mast of the config
        EXPECT_TRUE(first_points[k].isApprox(expected[k].points_robot.front() - Eigen::Vector3f(0, 0, 0.5f), 1e-5f));
    }
    std::vector<Eigen::Isometry3d> poses;
    odometry.receive(
        [&](const void* s) {
            Eigen::Isometry3d T;
            ASSERT_TRUE(odometryPose(*static_cast<const nav_msgs_msg_dds__Odometry_*>(s), T));
            poses.push_back(T);
        },
        [&] { return poses.size() == expected.size(); }, 5s);
    ASSERT_EQ(poses.size(), expected.size());
    EXPECT_TRUE(poses.back().isApprox(expected.back().T_world_robot, 1e-9));
}

TEST(PlayCli, ErrorsNameTheFile) {
    test::ChildOptions child;
    child.stderr_path = scratch("missing.err");
    EXPECT_EQ(test::waitForExit(test::spawnStairmap({"play", "/no/such.rawlog", "--ros2"}, child), 30s), 2);
    EXPECT_NE(test::fileText(child.stderr_path).find("/no/such.rawlog"), std::string::npos);
    child.stderr_path = scratch("transport.err");
    EXPECT_EQ(test::waitForExit(test::spawnStairmap({"play", kRawlog}, child), 30s), 2);
    EXPECT_NE(test::fileText(child.stderr_path).find("--ros2"), std::string::npos);
    child.stderr_path = scratch("topic.err");
    EXPECT_EQ(test::waitForExit(test::spawnStairmap({"play", kRawlog, "--ros2", "--poses", kPoses,
                                                     "--points-topic", "bad topic"}, child), 30s), 2);
    EXPECT_NE(test::fileText(child.stderr_path).find("bad topic"), std::string::npos);
}

}  // namespace
}  // namespace stairmap::ros2
