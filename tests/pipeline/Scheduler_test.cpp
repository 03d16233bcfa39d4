#include "pipeline/Scheduler.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stairmap::pipeline {
namespace {

Eigen::Isometry3d pose(double x, double y, double yaw_deg) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(x, y, 0.0);
    T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    return T;
}

SchedulingParams onlyDistance(double d) {
    SchedulingParams p;
    p.distance_m = d;
    p.angle_deg = 0;
    p.period_s = 0;
    return p;
}

TEST(Scheduler, FirstScanAlwaysRuns) {
    Scheduler scheduler(onlyDistance(1.0));
    EXPECT_TRUE(scheduler.update(0.0, pose(0, 0, 0)));
    EXPECT_FALSE(scheduler.update(0.1, pose(0, 0, 0)));
}

TEST(Scheduler, TriggersOnPathLengthNotDisplacement) {
    Scheduler scheduler(onlyDistance(1.0));
    ASSERT_TRUE(scheduler.update(0.0, pose(0, 0, 0)));
    // Back and forth: displacement stays 0.3 m but the path reaches 1.0 m at the 4th step.
    EXPECT_FALSE(scheduler.update(1, pose(0.3, 0, 0)));
    EXPECT_FALSE(scheduler.update(2, pose(0.0, 0, 0)));
    EXPECT_FALSE(scheduler.update(3, pose(0.3, 0, 0)));
    EXPECT_TRUE(scheduler.update(4, pose(0.0, 0, 0)));  // 1.2 m travelled
    EXPECT_FALSE(scheduler.update(5, pose(0.5, 0, 0)));  // counter restarted
    EXPECT_TRUE(scheduler.update(6, pose(1.0, 0, 0)));
}

TEST(Scheduler, TriggersOnRotation) {
    SchedulingParams p = onlyDistance(0);
    p.angle_deg = 30;
    Scheduler scheduler(p);
    ASSERT_TRUE(scheduler.update(0, pose(0, 0, 0)));
    EXPECT_FALSE(scheduler.update(1, pose(0, 0, 20)));
    EXPECT_TRUE(scheduler.update(2, pose(0, 0, 31)));
    EXPECT_FALSE(scheduler.update(3, pose(0, 0, 5)));  // 26 deg back from the last run
    EXPECT_TRUE(scheduler.update(4, pose(0, 0, -0.5)));
}

TEST(Scheduler, TriggersOnPeriodForStaticRobot) {
    SchedulingParams p = onlyDistance(0);
    p.period_s = 5;
    Scheduler scheduler(p);
    int runs = 0;
    for (int i = 0; i <= 100; ++i) runs += scheduler.update(0.1 * i, pose(1, 2, 3)) ? 1 : 0;
    EXPECT_EQ(runs, 3);  // t = 0, 5, 10 s (within rounding of 0.1 steps)
}

TEST(Scheduler, AllTriggersOffRunsOnlyOnce) {
    Scheduler scheduler(onlyDistance(0));
    EXPECT_TRUE(scheduler.update(0, pose(0, 0, 0)));
    EXPECT_FALSE(scheduler.update(100, pose(50, 0, 90)));
}

TEST(Scheduler, NonFiniteParamThrows) {
    SchedulingParams p;
    p.angle_deg = NAN;
    EXPECT_THROW(Scheduler{p}, std::invalid_argument);
}

}  // namespace
}  // namespace stairmap::pipeline
