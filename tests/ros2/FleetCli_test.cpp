// `stairmap fleet --ros2` as a separate process between two robots' landmark publishers (as
// `stairmap live --ros2 --robot-name` would run them) and a plain subscriber of the fleet map:
// one landmark per staircase in the first robot's frame; robot B killed mid-run keeps its
// landmarks when robot A's map grows.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "StairmapMessages.h"
#include "apps/ChildProcess.h"
#include "fleetlive/FleetScenario.h"
#include "ros2/LandmarkMessages.h"
#include "ros2/Ros2LandmarkPublisher.h"
#include "ros2/TestSubscriber.h"

namespace stairmap::ros2 {
namespace {

using namespace std::chrono_literals;

std::string scratch(const std::string& name) {
    const auto dir = std::filesystem::path(STAIRMAP_TEST_TMP) / ("ros2_fleet_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

std::unique_ptr<Ros2LandmarkPublisher> robotPublisher(const std::string& name) {
    Ros2PublisherOptions options;
    options.robot_name = name;
    return std::make_unique<Ros2LandmarkPublisher>(options);
}

TEST(FleetCli, MergesTwoRobotsAndKeepsASilentRobotsLandmarks) {
    const std::string tag = std::to_string(getpid());
    const std::string a = "fa" + tag, b = "fb" + tag, fleet = "fleet" + tag;
    const fleet::Transform4 T_A_B{6.0, -3.0, 0.5, 2.0};
    auto robot_a = robotPublisher(a);
    auto robot_b = robotPublisher(b);
    robot_a->publish(fleetlive::test::robotA().staircases, {}, 100.0);
    robot_b->publish(fleetlive::test::robotB(T_A_B).staircases, {}, 100.0);

    test::TestSubscriber fleet_map(&stairmap_msgs_msg_dds__StaircaseArray__desc,
                                   ddsTopicName("/stairmap/staircases", fleet), Reliability::Reliable,
                                   Durability::TransientLocal);
    test::ChildOptions child;
    child.stderr_path = scratch("fleet.err");
    const pid_t pid = test::spawnStairmap(
        {"fleet", "--ros2", "--robot", a, "--robot", b, "--fleet-name", fleet, "--duration", "60"}, child);
    LandmarkMapState latest;
    auto take = [&](const void* s) {
        latest = landmarkState(*static_cast<const stairmap_msgs_msg_dds__StaircaseArray_*>(s));
    };
    // 3 shared flights + B's own, in A's frame
    const bool merged = fleet_map.receive(take, [&] { return latest.staircases.size() == 4; }, 20s);
    EXPECT_TRUE(merged) << latest.staircases.size() << " staircases; " << test::fileText(child.stderr_path);
    const Eigen::Vector3d b_only = fleetlive::test::mapOf({fleetlive::test::onlyB()}).staircases[0].stairs.location;
    bool b_only_in_place = false;
    for (const auto& l : latest.staircases) b_only_in_place |= (l.stairs.location - b_only).norm() < 0.05;
    EXPECT_TRUE(b_only_in_place);

    robot_b.reset();  // robot B goes away
    const auto published = std::chrono::steady_clock::now();
    robot_a->publish(fleetlive::test::robotA(true).staircases, {}, 101.0);  // A finds a 5th flight
    const bool kept = fleet_map.receive(take, [&] { return latest.staircases.size() == 5; }, 20s);
    // reported, not asserted (timing belongs to benchmarks): robot publish -> fleet map received
    const double latency_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - published).count();
    RecordProperty("fleet_latency_ms", std::to_string(latency_ms));
    std::cout << "robot map -> fleet map latency: " << latency_ms << " ms\n";
    EXPECT_TRUE(kept) << latest.staircases.size() << " staircases; " << test::fileText(child.stderr_path);
    ::kill(pid, SIGINT);
    EXPECT_EQ(test::waitForExit(pid, 20s), 0) << test::fileText(child.stderr_path);
}

TEST(FleetCli, NeedsRobotsAndTransport) {
    test::ChildOptions child;
    child.stderr_path = scratch("usage.err");
    EXPECT_EQ(test::waitForExit(test::spawnStairmap({"fleet", "--robot", "a"}, child), 20s), 2);
    EXPECT_NE(test::fileText(child.stderr_path).find("--ros2"), std::string::npos);
    EXPECT_EQ(test::waitForExit(test::spawnStairmap({"fleet", "--ros2"}, child), 20s), 2);
    EXPECT_NE(test::fileText(child.stderr_path).find("--robot"), std::string::npos);
}

TEST(FleetCli, AnOutFolderThatCannotBeMadeFailsAtOnce) {
    const std::string file = scratch("not_a_folder");
    std::ofstream(file) << "x";
    test::ChildOptions child;
    child.stderr_path = scratch("out.err");
    const std::string out = file + "/fleet";
    EXPECT_EQ(test::waitForExit(test::spawnStairmap({"fleet", "--ros2", "--robot", "a", "--out", out}, child), 20s), 2);
    EXPECT_NE(test::fileText(child.stderr_path).find(out), std::string::npos) << test::fileText(child.stderr_path);
}

}  // namespace
}  // namespace stairmap::ros2
