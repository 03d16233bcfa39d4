// The issue 11 CI test: three processes on loopback. `stairmap play --ros2` publishes the bundled
// ascending sequence; `stairmap live --ros2 --robot-name R` maps it; this process, a plain
// subscriber of /R/stairmap/markers and /R/stairmap/staircases, must see the staircase with the
// ground truth's rise, run and width (datasets/sequences/ascending/gt.json: 0.17, 0.28, 1.2 m).
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <filesystem>

#include "StairmapMessages.h"
#include "apps/ChildProcess.h"
#include "ros2/LandmarkMarkers.h"
#include "ros2/LandmarkMessages.h"
#include "ros2/TestSubscriber.h"

namespace stairmap::ros2 {
namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;

const std::string kData = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/sequences/ascending/";
const std::string kConfig = std::string(STAIRMAP_SOURCE_DIR) + "/config/sim_legged_vlp16.ini";

TEST(LiveRos2Cli, PlayToLiveToMarkerSubscriber) {
    const std::string tag = std::to_string(getpid());
    const std::string robot = "live" + tag, points = "/lt" + tag + "/points", odom = "/lt" + tag + "/odom";
    const fs::path dir = fs::path(STAIRMAP_TEST_TMP) / ("ros2_live_" + tag);
    fs::remove_all(dir);
    fs::create_directories(dir);
    test::TestSubscriber markers(&visualization_msgs_msg_dds__MarkerArray__desc,
                                 ddsTopicName("/stairmap/markers", robot), Reliability::Reliable,
                                 Durability::TransientLocal);
    test::TestSubscriber staircases(&stairmap_msgs_msg_dds__StaircaseArray__desc,
                                    ddsTopicName("/stairmap/staircases", robot), Reliability::Reliable,
                                    Durability::TransientLocal);
    test::ChildOptions live_child, play_child;
    live_child.stderr_path = (dir / "live.err").string();
    play_child.stderr_path = (dir / "play.err").string();
    const pid_t live = test::spawnStairmap({"live", "--ros2", "--points-topic", points, "--odom-topic", odom,
                                            "--robot-name", robot, "--config", kConfig, "--out",
                                            (dir / "out").string(), "--duration", "60"},
                                           live_child);
    // the sensor of the sequence is 0.15 m above the robot origin (gt.json T_robot_sensor); play and
    // live both take it from the same [sensor] pose_* (the preset's 0 here: the frames cancel out)
    const pid_t play = test::spawnStairmap({"play", kData + "seq_ascending.rawlog", "--poses", kData + "poses.tum",
                                            "--config", kConfig, "--ros2", "--rate", "2", "--points-topic",
                                            points, "--odom-topic", odom, "--wait-subscribers", "20"},
                                           play_child);
    EXPECT_EQ(test::waitForExit(play, 60s), 0) << test::fileText(play_child.stderr_path);

    std::vector<std::string> labels;
    markers.receive(
        [&](const void* s) {
            const auto& array = *static_cast<const visualization_msgs_msg_dds__MarkerArray_*>(s);
            labels.clear();
            for (uint32_t i = 0; i < array.markers._length; ++i)
                if (array.markers._buffer[i].type == kTextViewFacing) labels.push_back(array.markers._buffer[i].text);
        },
        [&] { return !labels.empty(); }, 20s);
    LandmarkMapState map;
    staircases.receive(
        [&](const void* s) { map = landmarkState(*static_cast<const stairmap_msgs_msg_dds__StaircaseArray_*>(s)); },
        [&] { return !map.staircases.empty(); }, 20s);
    ::kill(live, SIGINT);
    EXPECT_EQ(test::waitForExit(live, 60s), 0) << test::fileText(live_child.stderr_path);

    ASSERT_EQ(labels.size(), 1u) << test::fileText(live_child.stderr_path);
    EXPECT_NE(labels[0].find("stair 0:"), std::string::npos) << labels[0];
    ASSERT_EQ(map.staircases.size(), 1u);
    const Staircase& stairs = map.staircases[0].stairs;
    EXPECT_NEAR(stairs.step_height, 0.17, 0.02);
    EXPECT_NEAR(stairs.step_depth, 0.28, 0.03);
    EXPECT_NEAR(stairs.step_width, 1.2, 0.3);
    EXPECT_TRUE(fs::exists(dir / "out" / "landmarks.json"));
}

}  // namespace
}  // namespace stairmap::ros2
