// stairmap's ROS 2 endpoints talking over DDS on 127.0.0.1 inside one process (separate
// participants, as separate nodes): the scan publisher feeding Ros2Source, malformed and
// pose-less clouds counted, and the landmark publisher seen by a plain subscriber.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <mutex>
#include <thread>

#include "StairmapMessages.h"
#include "map/LandmarkMap.h"
#include "ros2/LandmarkMarkers.h"
#include "ros2/MessageBuilders.h"
#include "ros2/Ros2LandmarkPublisher.h"
#include "ros2/Ros2ScanPublisher.h"
#include "ros2/Ros2Source.h"
#include "ros2/TestSubscriber.h"

namespace stairmap::ros2 {
namespace {

using namespace std::chrono_literals;

std::string uniqueTopic(const std::string& name) { return "/looptest_" + std::to_string(getpid()) + "/" + name; }

/// Collects what a source pushes.
struct CollectingSink : live::ScanSink {
    void push(Scan scan) override {
        std::lock_guard<std::mutex> lock(mutex);
        scans.push_back(std::move(scan));
    }
    std::size_t size() {
        std::lock_guard<std::mutex> lock(mutex);
        return scans.size();
    }
    std::mutex mutex;
    std::vector<Scan> scans;
};

/// Runs a source on its own thread for the duration of a test.
struct RunningSource {
    explicit RunningSource(const Ros2SourceOptions& options) : source(options) {
        thread = std::thread([this] { source.run(sink, stop); });
    }
    ~RunningSource() {
        stop = true;
        thread.join();
    }
    bool waitFor(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
        const auto end = std::chrono::steady_clock::now() + timeout;
        while (!done() && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(10ms);
        return done();
    }
    Ros2Source source;
    CollectingSink sink;
    std::atomic<bool> stop{false};
    std::thread thread;
};

Eigen::Isometry3d robotPose(double x, double yaw) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T.translation() = Eigen::Vector3d(x, 0.0, 0.5);
    return T;
}

TEST(Ros2Loopback, PlayedScansArriveInTheRobotFrameWithTheirPoses) {
    Ros2SourceOptions options;
    options.points_topic = uniqueTopic("points");
    options.odom_topic = uniqueTopic("odom");
    options.T_robot_sensor.translation() = Eigen::Vector3d(0.2, 0.0, 0.4);  // lidar on a mast
    RunningSource live(options);
    Ros2PlayOptions play;
    play.points_topic = options.points_topic;
    play.odom_topic = options.odom_topic;
    Ros2ScanPublisher publisher(play);
    ASSERT_EQ(publisher.waitForSubscribers(5.0, [] { return false; }), 1);
    for (int k = 0; k < 5; ++k) {
        Scan scan;
        scan.stamp_s = 1000.0 + 0.1 * k;
        scan.T_world_robot = robotPose(0.1 * k, 0.05 * k);
        publisher.publish(scan, PointCloud{{1.0f, float(k), 0.0f}, {2.0f, 0.0f, -0.4f}});
        std::this_thread::sleep_for(20ms);
    }
    ASSERT_TRUE(live.waitFor([&] { return live.sink.size() == 5; }, 5s)) << live.sink.size();
    for (int k = 0; k < 5; ++k) {
        const Scan& scan = live.sink.scans[k];
        EXPECT_NEAR(scan.stamp_s, 1000.0 + 0.1 * k, 1e-6);
        EXPECT_TRUE(scan.T_world_robot.isApprox(robotPose(0.1 * k, 0.05 * k), 1e-9));
        ASSERT_EQ(scan.points_robot.size(), 2u);
        EXPECT_TRUE(scan.points_robot[0].isApprox(Eigen::Vector3f(1.2f, float(k), 0.4f)));
        EXPECT_TRUE(scan.points_robot[1].isApprox(Eigen::Vector3f(2.2f, 0.0f, 0.0f)));
    }
    EXPECT_EQ(live.source.counters().at("clouds_without_pose"), 0u);
}

TEST(Ros2Loopback, ThePublisherWaitsForTheOdometryReaderMatchedAfterTheCloudReader) {
    // A subscriber whose odometry reader comes up 300 ms after its cloud reader (as discovery
    // may order them): a scan published once waitForSubscribers returns must reach both.
    Ros2PlayOptions play;
    play.points_topic = uniqueTopic("late_odom_points");
    play.odom_topic = uniqueTopic("late_odom_odom");
    Ros2ScanPublisher publisher(play);
    test::TestSubscriber clouds(&sensor_msgs_msg_dds__PointCloud2__desc, ddsTopicName(play.points_topic));
    std::unique_ptr<test::TestSubscriber> odometry;
    std::thread late([&] {
        std::this_thread::sleep_for(300ms);
        odometry = std::make_unique<test::TestSubscriber>(&nav_msgs_msg_dds__Odometry__desc,
                                                          ddsTopicName(play.odom_topic));
    });
    const int subscribers = publisher.waitForSubscribers(5.0, [] { return false; });
    Scan scan;
    scan.stamp_s = 7.0;
    scan.T_world_robot = robotPose(1.0, 0.2);
    publisher.publish(scan, PointCloud{{1.0f, 0.0f, 0.0f}});
    late.join();
    ASSERT_EQ(subscribers, 1);
    int poses = 0;
    EXPECT_TRUE(odometry->receive([&](const void*) { ++poses; }, [&] { return poses > 0; }, 3s))
        << "the scan's odometry was written before its subscriber matched";
}

TEST(Ros2Loopback, BadCloudsAndMissingPosesAreCountedNotFatal) {
    Ros2SourceOptions options;
    options.points_topic = uniqueTopic("bad_points");
    options.odom_topic = uniqueTopic("bad_odom");
    options.pose_wait_s = 0.3;
    RunningSource live(options);
    DdsEntity participant = createParticipant();
    const dds_entity_t topic =
        createTopic(participant.get(), &sensor_msgs_msg_dds__PointCloud2__desc, ddsTopicName(options.points_topic));
    const dds_entity_t writer = createWriter(participant.get(), topic, Reliability::Reliable,
                                             Durability::Volatile, 10, options.points_topic);
    for (int i = 0; i < 200 && matchedReaders(writer) == 0; ++i) std::this_thread::sleep_for(10ms);
    ASSERT_EQ(matchedReaders(writer), 1);
    // a cloud whose z field is missing, a truncated one, and a good one that never gets a pose
    CloudMessage no_z(PointCloud{{1, 2, 3}}, 5.0, "lidar");
    auto sample = *no_z.sample();
    sample.fields._length = 2;
    dds_write(writer, &sample);
    CloudMessage truncated(PointCloud{{1, 2, 3}, {4, 5, 6}}, 5.1, "lidar");
    sample = *truncated.sample();
    sample.data._length = 13;
    dds_write(writer, &sample);
    CloudMessage good(PointCloud{{1, 2, 3}}, 5.2, "lidar");
    dds_write(writer, good.sample());
    ASSERT_TRUE(live.waitFor([&] { return live.source.counters().at("clouds_without_pose") == 1; }, 5s));
    const auto counters = live.source.counters();
    EXPECT_EQ(counters.at("clouds_received"), 3u);
    EXPECT_EQ(counters.at("clouds_without_xyz"), 1u);
    EXPECT_EQ(counters.at("malformed_clouds"), 1u);
    EXPECT_EQ(live.sink.size(), 0u);
}

StaircaseLandmark landmark(int id, double x) {
    StaircaseLandmark l;
    l.id = id;
    for (int k = 0; k < 3; ++k) {
        StairEdge e;
        e.start = Eigen::Vector3d(x, 0.3 * k + 0.5, 0.17 * (k + 1));
        e.end = Eigen::Vector3d(x, 0.3 * k - 0.5, 0.17 * (k + 1));
        l.stairs.steps.push_back(e);
    }
    l.stairs.step_height = 0.17;
    return l;
}

TEST(Ros2Loopback, LandmarkPublisherReachesLateSubscribersAndClearsRemovedLandmarks) {
    Ros2PublisherOptions options;
    options.robot_name = "looptest_" + std::to_string(getpid());
    Ros2LandmarkPublisher publisher(options);
    EXPECT_EQ(publisher.markersTopic(), "rt/" + options.robot_name + "/stairmap/markers");
    publisher.publish({landmark(0, 1.0), landmark(1, 4.0)}, {}, 50.0);
    // a subscriber that joins after the first publish gets it (transient-local)
    test::TestSubscriber markers(&visualization_msgs_msg_dds__MarkerArray__desc, publisher.markersTopic(),
                                 Reliability::Reliable, Durability::TransientLocal);
    test::TestSubscriber staircases(&stairmap_msgs_msg_dds__StaircaseArray__desc, publisher.staircasesTopic(),
                                    Reliability::Reliable, Durability::TransientLocal);
    std::vector<std::vector<std::pair<std::string, int>>> received;  // per array: (ns, action)
    auto take_markers = [&](const void* s) {
        const auto& array = *static_cast<const visualization_msgs_msg_dds__MarkerArray_*>(s);
        received.emplace_back();
        for (uint32_t i = 0; i < array.markers._length; ++i)
            received.back().emplace_back(array.markers._buffer[i].ns, array.markers._buffer[i].action);
    };
    ASSERT_TRUE(markers.receive(take_markers, [&] { return received.size() == 1; }, 5s));
    ASSERT_EQ(received[0].size(), 6u);
    EXPECT_EQ(received[0][0], std::make_pair(std::string("staircase_0"), 0));
    EXPECT_EQ(received[0][3].first, "staircase_1");
    int staircase_count = -1;
    ASSERT_TRUE(staircases.receive(
        [&](const void* s) {
            staircase_count = int(static_cast<const stairmap_msgs_msg_dds__StaircaseArray_*>(s)->staircases._length);
        },
        [&] { return staircase_count >= 0; }, 5s));
    EXPECT_EQ(staircase_count, 2);
    // landmark 0 disappears (e.g. joined into another): DELETEALL first, then the rest
    publisher.publish({landmark(1, 4.0)}, {}, 51.0);
    ASSERT_TRUE(markers.receive(take_markers, [&] { return received.size() == 2; }, 5s));
    ASSERT_EQ(received[1].size(), 4u);
    EXPECT_EQ(received[1][0].second, int(kDeleteAll));
    EXPECT_EQ(received[1][1].first, "staircase_1");
    // growing again needs no DELETEALL
    publisher.publish({landmark(1, 4.0), landmark(2, 8.0)}, {}, 52.0);
    ASSERT_TRUE(markers.receive(take_markers, [&] { return received.size() == 3; }, 5s));
    EXPECT_EQ(received[2].size(), 6u);
    EXPECT_EQ(received[2][0].second, int(kAdd));
}

TEST(Ros2Loopback, BadNamesAreRefusedWithTheName) {
    Ros2SourceOptions options;
    options.points_topic = "/points with space";
    try {
        Ros2Source source(options);
        FAIL() << "accepted a topic name with spaces";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("points with space"), std::string::npos) << e.what();
    }
    EXPECT_EQ(ddsTopicName("/points"), "rt/points");
    EXPECT_EQ(ddsTopicName("stairmap/markers", "/robot_a/"), "rt/robot_a/stairmap/markers");
}

}  // namespace
}  // namespace stairmap::ros2
