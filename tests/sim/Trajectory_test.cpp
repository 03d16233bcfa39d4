// Scripted trajectories (timing, heading, heights) and drift on the reported poses.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/GroundTruth.h"
#include "sim/CloudSampler.h"
#include "sim/Trajectory.h"

namespace stairmap::sim {
namespace {

double yawOf(const Eigen::Isometry3d& T) { return std::atan2(T.linear()(1, 0), T.linear()(0, 0)); }

TEST(Trajectory, StraightPathAtSpeedAndRate) {
    TrajectoryParams p;
    p.waypoints = {{0, 0, 0}, {4, 0, 0}};
    p.speed_mps = 1.0;
    p.scan_rate_hz = 2.0;
    p.start_time_s = 10.0;
    p.base_height_m = 0.3;
    const auto samples = sampleTrajectory(p);
    ASSERT_EQ(samples.size(), 9u);  // t = 0, 0.5, ..., 4.0
    for (std::size_t k = 0; k < samples.size(); ++k) {
        EXPECT_NEAR(samples[k].stamp_s, 10.0 + 0.5 * k, 1e-12);
        EXPECT_NEAR(samples[k].T_world_robot_true.translation().x(), 0.5 * k, 1e-9);
        EXPECT_NEAR(samples[k].T_world_robot_true.translation().z(), 0.3, 1e-12);
        EXPECT_TRUE(samples[k].T_world_robot_reported.isApprox(samples[k].T_world_robot_true));
    }
}

TEST(Trajectory, TurnsInPlaceThenClimbs) {
    TrajectoryParams p;
    p.waypoints = {{0, 0, 0}, {2, 0, 0}, {2, 2, 1}};
    p.speed_mps = 1.0;
    p.yaw_rate_dps = 90.0;
    p.scan_rate_hz = 10.0;
    p.base_height_m = 0.0;
    const auto s = sampleTrajectory(p);
    // Drive 2 s, turn 90 deg in 1 s, climb sqrt(5) m.
    const double total = 2.0 + 1.0 + std::sqrt(5.0);
    EXPECT_NEAR(s.back().stamp_s - s.front().stamp_s, std::floor(total * 10) / 10, 1e-6);
    EXPECT_NEAR(yawOf(s[15].T_world_robot_true), 0.0, 1e-9);                   // still driving
    EXPECT_NEAR(yawOf(s[25].T_world_robot_true), M_PI / 4, 1e-6);              // half-way through the turn
    EXPECT_NEAR(s[25].T_world_robot_true.translation().x(), 2.0, 1e-9);
    const auto& mid = s[30 + 11].T_world_robot_true.translation();             // 1.1 s into the climb
    EXPECT_NEAR(mid.z(), 1.1 / std::sqrt(5.0), 1e-6);
}

TEST(Trajectory, DriftMovesReportedPosesOnlyAndIsSeeded) {
    TrajectoryParams p;
    p.waypoints = {{0, 0, 0}, {20, 0, 0}};
    auto a = sampleTrajectory(p);
    auto b = a;
    DriftParams drift;
    drift.xy_std_per_m = 0.02;
    drift.yaw_std_deg_per_m = 0.5;
    drift.seed = 3;
    applyDrift(a, drift);
    applyDrift(b, drift);
    const auto truth = sampleTrajectory(p);
    double final_error = (a.back().T_world_robot_reported.translation() -
                          a.back().T_world_robot_true.translation()).norm();
    EXPECT_GT(final_error, 1e-3);
    EXPECT_LT(final_error, 3.0);
    for (std::size_t k = 0; k < a.size(); ++k) {
        EXPECT_TRUE(a[k].T_world_robot_true.isApprox(truth[k].T_world_robot_true));
        EXPECT_TRUE(a[k].T_world_robot_reported.isApprox(b[k].T_world_robot_reported));
    }
    EXPECT_GT(a.back().covariance(0, 0), a[1].covariance(0, 0));
}

TEST(Trajectory, InvalidParamsNameTheField) {
    TrajectoryParams p;
    p.waypoints = {{0, 0, 0}};
    try {
        sampleTrajectory(p);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("waypoints"), std::string::npos);
    }
    p.waypoints = {{0, 0, 0}, {1, 0, 0}};
    p.speed_mps = -1.0;
    EXPECT_THROW(sampleTrajectory(p), std::invalid_argument);
}

TEST(CloudSampler, TruthInRobotFrameSetsSeenAsFromTheObserverFloor) {
    SceneTruth world;
    StaircaseTruth s;
    s.bottom_z = 0.0;
    s.top_z = 1.0;
    s.nosings = {{{2, -0.5, 0.2}, {2, 0.5, 0.2}}};
    world.staircases = {s};
    world.floor_heights = {0.0, 1.0};
    const Eigen::Isometry3d T_world_robot = robotPoseAt({0, 0, 0}, M_PI / 2, 0.4);
    auto robot = truthInRobotFrame(world, T_world_robot, 0.0);
    EXPECT_EQ(robot.frame, "robot");
    ASSERT_TRUE(robot.staircases[0].seen_as);
    EXPECT_EQ(*robot.staircases[0].seen_as, StairDirection::Ascending);
    EXPECT_NEAR(*robot.observer_floor_z, -0.4, 1e-12);
    // Robot facing +y: the nosing at world x = 2 is on its right, y = -2.
    EXPECT_NEAR(robot.staircases[0].nosings[0].centre().y(), -2.0, 1e-9);
    EXPECT_NEAR(robot.staircases[0].nosings[0].centre().z(), -0.2, 1e-9);
    EXPECT_NEAR(robot.floor_heights[1], 0.6, 1e-12);
    robot = truthInRobotFrame(world, robotPoseAt({3, 0, 1}, 0, 0.4), 1.0);
    EXPECT_EQ(*robot.staircases[0].seen_as, StairDirection::Descending);
    robot = truthInRobotFrame(world, robotPoseAt({3, 0, 0.5}, 0, 0.4), 0.5);
    EXPECT_FALSE(robot.staircases[0].seen_as);
}

TEST(TrajectorySway, TiltsTrueAndReportedPosesByTheRequestedSpread) {
    TrajectoryParams p;
    p.waypoints = {{0, 0, 0}, {200, 0, 0}};
    p.speed_mps = 1.0;
    p.scan_rate_hz = 2.0;
    auto samples = sampleTrajectory(p);
    const auto level = samples;
    applySway(samples, {2.0, 5});
    double sum_sq = 0.0;
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const Eigen::Matrix3d R = samples[k].T_world_robot_true.linear();
        // Tilt = angle between the body's z axis and the world's; translation and yaw untouched.
        sum_sq += std::pow(std::acos(std::clamp(R(2, 2), -1.0, 1.0)), 2);
        EXPECT_TRUE(samples[k].T_world_robot_true.translation().isApprox(
            level[k].T_world_robot_true.translation()));
        EXPECT_NEAR(yawOf(samples[k].T_world_robot_true), yawOf(level[k].T_world_robot_true), 0.05);
        EXPECT_TRUE(samples[k].T_world_robot_reported.isApprox(samples[k].T_world_robot_true));
    }
    // Pitch and roll each N(0, 2 deg): the tilt's rms is sqrt(2) * 2 deg.
    const double rms_deg = std::sqrt(sum_sq / samples.size()) * 180.0 / M_PI;
    EXPECT_NEAR(rms_deg, std::sqrt(2.0) * 2.0, 0.3);
}

TEST(TrajectorySway, ZeroSwayLeavesPosesAloneAndBadSwayThrows) {
    TrajectoryParams p;
    p.waypoints = {{0, 0, 0}, {3, 1, 0}};
    auto samples = sampleTrajectory(p);
    const auto before = samples;
    applySway(samples, {0.0, 1});
    for (std::size_t k = 0; k < samples.size(); ++k)
        EXPECT_TRUE(samples[k].T_world_robot_true.isApprox(before[k].T_world_robot_true));
    EXPECT_THROW(applySway(samples, {-1.0, 1}), std::invalid_argument);
    EXPECT_THROW(applySway(samples, {11.0, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace stairmap::sim
