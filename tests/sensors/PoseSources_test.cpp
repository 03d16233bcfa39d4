// Robot poses for sensor scans: scans waiting a bounded time for their pose (PoseWait), and the
// --sensor source with a growing pose file (io/follow's GrowingTum, tested in tests/io/follow).
#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>

#include <fstream>
#include <iomanip>
#include <sstream>
#include <thread>

#include "SensorTestUtil.h"
#include "sensors/PoseWait.h"
#include "sensors/SensorSource.h"

using namespace stairmap;
using namespace stairmap::test;

namespace {

void append(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary | std::ios::app) << text;
}

std::string tumLine(double t, double x) {
    std::ostringstream s;
    s << std::setprecision(17) << t << " " << x << " 0 0 0 0 0 1\n";
    return s.str();
}

Scan scanAt(double stamp_s, std::size_t index) {
    Scan s;
    s.stamp_s = stamp_s;
    s.index = index;
    return s;
}

io::TumTrajectory lineTrajectory(double t0, double t1) {  // x = t
    io::TumTrajectory traj;
    for (double t = t0; t <= t1 + 1e-9; t += 1.0) {
        traj.append(t, Eigen::Isometry3d(Eigen::Translation3d(t, 0, 0)));
    }
    return traj;
}

}  // namespace

TEST(PoseWait, ReleasesInOrderOnceThePoseIsKnown) {
    sensors::PoseWait wait({/*max_wait_s=*/1.0, /*tolerance_s=*/0.0, /*max_pending=*/8});
    wait.add(scanAt(1.5, 0), 0.0);
    wait.add(scanAt(2.5, 1), 0.0);
    auto ready = wait.release(lineTrajectory(0, 2), 0.1);  // poses up to t = 2
    ASSERT_EQ(ready.size(), 1u);
    EXPECT_NEAR(ready[0].T_world_robot.translation().x(), 1.5, 1e-12);
    EXPECT_EQ(wait.pending(), 1u);
    ready = wait.release(lineTrajectory(0, 3), 0.2);  // the trajectory grew
    ASSERT_EQ(ready.size(), 1u);
    EXPECT_EQ(ready[0].index, 1u);
    EXPECT_NEAR(ready[0].T_world_robot.translation().x(), 2.5, 1e-12);
    EXPECT_EQ(wait.withoutPose(), 0u);
}

TEST(PoseWait, GivesUpAfterTheWaitAndOnScansOlderThanThePoses) {
    sensors::PoseWait wait({1.0, 0.0, 8});
    wait.add(scanAt(0.5, 0), 0.0);  // before the trajectory's start: never
    wait.add(scanAt(5.0, 1), 0.0);  // after its end: waits
    wait.add(scanAt(5.5, 2), 0.0);
    EXPECT_TRUE(wait.release(lineTrajectory(1, 3), 0.5).empty());
    EXPECT_EQ(wait.withoutPose(), 1u);
    EXPECT_EQ(wait.pending(), 2u);
    EXPECT_TRUE(wait.release(lineTrajectory(1, 3), 1.01).empty());  // waited out
    EXPECT_EQ(wait.withoutPose(), 3u);
    EXPECT_EQ(wait.pending(), 0u);
}

TEST(PoseWait, BoundedQueue) {
    sensors::PoseWait wait({10.0, 0.0, 3});
    for (std::size_t i = 0; i < 5; ++i) wait.add(scanAt(100.0 + double(i), i), 0.0);
    EXPECT_EQ(wait.pending(), 3u);
    EXPECT_EQ(wait.withoutPose(), 2u);
    const auto ready = wait.release(lineTrajectory(0, 110), 0.0);
    ASSERT_EQ(ready.size(), 3u);
    EXPECT_EQ(ready[0].index, 2u);  // the oldest two were given up
}

// Arrival stamps and a pose file written while the capture replays, by a writer that stamps
// with the same clock (as a pose estimator on the robot would): every scan gets its pose.
TEST(SensorSourcePoses, GrowingPoseFileWrittenDuringTheReplay) {
    const std::string dir = tempDir("growing_poses");
    const std::string poses = writeFile(dir + "/poses.tum", "");
    const std::string ini = writeFile(dir + "/s.ini", velodyneIni(kPcap, false));
    sensors::SensorSourceOptions options;
    options.poses_path = poses;
    options.pose_wait.max_wait_s = 1.0;
    auto source = sensors::makeSensorSource(ini, options);
    std::atomic<bool> writing{true};
    const double t_start = mrpt::Clock::toDouble(mrpt::Clock::now());
    std::thread writer([&] {  // x = seconds since the start, a pose every 20 ms, lines split
        while (writing) {
            const double t = mrpt::Clock::toDouble(mrpt::Clock::now());
            const std::string line = tumLine(t, t - t_start);
            append(poses, line.substr(0, 10));
            append(poses, line.substr(10));
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    });
    CollectingSink sink;
    std::atomic<bool> stop{false};
    source->run(sink, stop);
    writing = false;
    writer.join();
    const auto counters = source->counters();
    EXPECT_EQ(counters.at("scans_without_pose"), 0u);
    ASSERT_EQ(sink.scans.size(), 4u);
    for (const Scan& s : sink.scans) {
        EXPECT_NEAR(s.T_world_robot.translation().x(), s.stamp_s - t_start, 1e-6);
        EXPECT_GT(s.T_world_robot.translation().x(), 0.0);
    }
}

// Sensor stamps: the driver stamps the first rotation with the computer clock (no GPS fix yet),
// the others with the capture's GPS time (2016). A pose file in GPS time gives poses to those
// three; the first waits its bounded time and is counted as without pose.
TEST(SensorSourcePoses, SensorStampsAndAPoseThatNeverComes) {
    const std::string dir = tempDir("sensor_stamps");
    const double t0 = 1453364282.0;  // the capture's GPS time, 2016-01-21
    std::string text;
    for (int i = 0; i <= 10; ++i) text += tumLine(t0 + 0.1 * i, 0.1 * i);
    const std::string poses = writeFile(dir + "/poses.tum", text);
    sensors::SensorSourceOptions options;
    options.poses_path = poses;
    options.stamps = sensors::SensorSourceOptions::Stamps::Sensor;
    options.pose_wait.max_wait_s = 0.3;
    auto source = sensors::makeSensorSource(writeFile(dir + "/s.ini", velodyneIni(kPcap, true)), options);
    CollectingSink sink;
    std::atomic<bool> stop{false};
    const auto start = std::chrono::steady_clock::now();
    source->run(sink, stop);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
    const auto counters = source->counters();
    EXPECT_EQ(counters.at("scans"), 4u);
    EXPECT_EQ(counters.at("scans_without_pose"), 1u);
    ASSERT_EQ(sink.scans.size(), 3u);
    for (const Scan& s : sink.scans) {
        EXPECT_GT(s.stamp_s, t0);
        EXPECT_LT(s.stamp_s, t0 + 1.0);
        EXPECT_NEAR(s.T_world_robot.translation().x(), s.stamp_s - t0, 1e-6);
    }
}

// [sensor] pose_*: the configured mounting replaces the driver's (identity) pose.
TEST(SensorSourcePoses, SensorPoseFromTheStairmapConfig) {
    pipeline::SensorParams p;
    EXPECT_FALSE(sensors::sensorPoseOnRobot(p).has_value());
    p.pose_z_m = 1.25;
    p.pose_yaw_deg = 90.0;
    const auto T = sensors::sensorPoseOnRobot(p);
    ASSERT_TRUE(T.has_value());
    const Eigen::Vector3d q = *T * Eigen::Vector3d(1, 0, 0);  // sensor x -> robot y after yaw 90
    EXPECT_NEAR(q.x(), 0.0, 1e-12);
    EXPECT_NEAR(q.y(), 1.0, 1e-12);
    EXPECT_NEAR(q.z(), 1.25, 1e-12);

    const std::string dir = tempDir("sensor_pose");
    const std::string ini = writeFile(dir + "/s.ini", velodyneIni(kPcap, true));
    sensors::SensorSourceOptions plain, mounted;
    plain.static_robot = mounted.static_robot = true;
    mounted.T_robot_sensor = T;
    CollectingSink a, b;
    std::atomic<bool> stop{false};
    sensors::makeSensorSource(ini, plain)->run(a, stop);
    sensors::makeSensorSource(ini, mounted)->run(b, stop);
    ASSERT_EQ(a.scans.size(), 4u);
    ASSERT_EQ(b.scans.size(), 4u);
    ASSERT_EQ(a.scans[1].points_robot.size(), b.scans[1].points_robot.size());
    for (std::size_t i = 0; i < a.scans[1].points_robot.size(); i += 97) {
        const Eigen::Vector3f expected = (T->cast<float>() * a.scans[1].points_robot[i]);
        EXPECT_LT((b.scans[1].points_robot[i] - expected).norm(), 1e-4f) << i;
    }
}
