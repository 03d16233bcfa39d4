#include "pipeline/Submap.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stairmap::pipeline {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Robot at (10, 5, 2), yaw 90 deg, pitched 20 deg nose-down and rolled 10 deg.
Eigen::Isometry3d tiltedRobot() {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(10, 5, 2);
    T.linear() = (Eigen::AngleAxisd(90 * kDeg, Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(20 * kDeg, Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(10 * kDeg, Eigen::Vector3d::UnitX()))
                     .toRotationMatrix();
    return T;
}

TEST(Submap, GravityFrameKeepsYawOnly) {
    const Eigen::Isometry3d T_world_grav = gravityAlignedFrame(tiltedRobot());
    EXPECT_NEAR(robotYaw(tiltedRobot()), 90 * kDeg, 1e-12);
    EXPECT_TRUE(T_world_grav.translation().isApprox(Eigen::Vector3d(10, 5, 2)));
    // z stays world up: roll and pitch are removed.
    EXPECT_TRUE((T_world_grav.linear() * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitZ()));
    // x points along world +y (the heading).
    EXPECT_TRUE((T_world_grav.linear() * Eigen::Vector3d::UnitX())
                    .isApprox(Eigen::Vector3d::UnitY(), 1e-12));
}

TEST(Submap, KnownWorldPointLandsAtRobotFrameCoordinates) {
    // A point 3 m ahead of the robot (world +y), 1 m to its left (world -x), on the floor 0.5 m
    // below the robot origin: grav coordinates (3, 1, -0.5) whatever the robot's roll and pitch.
    ScanWindow window(5, 10.0);
    window.push(0.0, {Eigen::Vector3f(9, 8, 1.5), Eigen::Vector3f(10, 20, 2)});  // 2nd: too far
    const PointCloud submap = window.extractSubmap(gravityAlignedFrame(tiltedRobot()), 6.0, 0.0);
    ASSERT_EQ(submap.size(), 1u);
    EXPECT_NEAR(submap[0].x(), 3.0f, 1e-5);
    EXPECT_NEAR(submap[0].y(), 1.0f, 1e-5);
    EXPECT_NEAR(submap[0].z(), -0.5f, 1e-5);
}

TEST(Submap, RadiusIsHorizontalOnly) {
    ScanWindow window(5, 10.0);
    window.push(0.0, {Eigen::Vector3f(2, 0, 30)});  // far above, horizontally close
    EXPECT_EQ(window.extractSubmap(Eigen::Isometry3d::Identity(), 3.0, 0.0).size(), 1u);
}

TEST(Submap, WindowDropsOldAndExcessScans) {
    ScanWindow window(3, 1.0);
    for (int i = 0; i < 5; ++i) window.push(0.1 * i, PointCloud(10, Eigen::Vector3f(1, 0, 0)));
    EXPECT_EQ(window.numScans(), 3u);
    window.push(2.0, PointCloud(4, Eigen::Vector3f(1, 0, 0)));  // the others are > 1 s older
    EXPECT_EQ(window.numScans(), 1u);
    EXPECT_EQ(window.numPoints(), 4u);
}

TEST(Submap, VoxelDownsampleKeepsOnePointPerCell) {
    const PointCloud cloud = {{0.01f, 0.01f, 0.01f}, {0.02f, 0.03f, 0.04f}, {0.06f, 0.0f, 0.0f},
                              {NAN, 0.f, 0.f},       {-0.01f, 0.f, 0.f}};
    const PointCloud out = voxelDownsample(cloud, 0.05);
    EXPECT_EQ(out.size(), 3u);  // [0,0.05)^3, [0.05,0.1) x, [-0.05,0) x; NaN dropped
}

TEST(Submap, EmptyWindowGivesEmptySubmap) {
    ScanWindow window(3, 1.0);
    EXPECT_TRUE(window.extractSubmap(Eigen::Isometry3d::Identity(), 5.0, 0.02).empty());
}

}  // namespace
}  // namespace stairmap::pipeline
