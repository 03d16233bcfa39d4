#include <gtest/gtest.h>

#include <cmath>

#include "ros2/PoseBuffer.h"

namespace stairmap::ros2 {
namespace {

Eigen::Isometry3d pose(double x, double yaw) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T.translation() = Eigen::Vector3d(x, 2.0 * x, 0.0);
    return T;
}

TEST(PoseBuffer, InterpolatesPositionAndYawBetweenNeighbours) {
    PoseBuffer buffer;
    ASSERT_TRUE(buffer.add(10.0, pose(0.0, 0.0)));
    ASSERT_TRUE(buffer.add(10.1, pose(1.0, 0.4)));
    ASSERT_TRUE(buffer.add(10.2, pose(3.0, 0.4)));
    Eigen::Isometry3d T;
    ASSERT_EQ(buffer.lookup(10.025, T), PoseLookup::Found);
    EXPECT_NEAR(T.translation().x(), 0.25, 1e-9);
    EXPECT_NEAR(T.translation().y(), 0.5, 1e-9);
    EXPECT_NEAR(std::atan2(T.linear()(1, 0), T.linear()(0, 0)), 0.1, 1e-9);
    ASSERT_EQ(buffer.lookup(10.15, T), PoseLookup::Found);
    EXPECT_NEAR(T.translation().x(), 2.0, 1e-9);
}

TEST(PoseBuffer, SaysWhyThereIsNoPose) {
    PoseBufferParams params;
    params.max_gap_s = 0.5;
    params.tolerance_s = 0.01;
    PoseBuffer buffer(params);
    Eigen::Isometry3d T;
    EXPECT_EQ(buffer.lookup(1.0, T), PoseLookup::NotYet);  // nothing yet
    buffer.add(1.0, pose(0, 0));
    buffer.add(3.0, pose(1, 0));
    EXPECT_EQ(buffer.lookup(3.5, T), PoseLookup::NotYet);  // newer than the newest pose
    EXPECT_EQ(buffer.lookup(0.5, T), PoseLookup::TooOld);
    EXPECT_EQ(buffer.lookup(2.0, T), PoseLookup::Gap);     // 2 s between the neighbours
    EXPECT_EQ(buffer.lookup(3.005, T), PoseLookup::Found); // within the tolerance
    EXPECT_FALSE(buffer.add(2.5, pose(0, 0)));             // out of order
    EXPECT_FALSE(buffer.add(4.0, pose(std::nan(""), 0)));
    EXPECT_EQ(buffer.size(), 2u);
}

TEST(PoseBuffer, MemoryIsBounded) {
    PoseBufferParams params;
    params.max_poses = 100;
    PoseBuffer buffer(params);
    for (int i = 0; i < 1000; ++i) buffer.add(i * 0.001, pose(i, 0));
    EXPECT_EQ(buffer.size(), 100u);
}

}  // namespace
}  // namespace stairmap::ros2
