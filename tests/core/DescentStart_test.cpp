// The surface a descending flight starts from: level surfaces (a landing, the steps above it)
// or a ramp, on exact synthetic geometry.
#include "core/DescentStart.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

namespace stairmap {
namespace {

constexpr double kFloorZ = -0.5;  // the robot's floor
constexpr double kRise = 0.15;

/// A descending flight down +x: edges across y in [-1, 1] at the given x and heights; steps[0]
/// is its first (highest) edge.
Staircase descent(const std::vector<std::pair<double, double>>& x_z) {
    Staircase s;
    s.direction = StairDirection::Descending;
    for (const auto& [x, z] : x_z) {
        StairEdge e;
        e.start = {x, 1.0, z};
        e.end = {x, -1.0, z};
        e.num_points = 20;
        s.steps.push_back(e);
    }
    s.step_height = kRise;
    s.step_depth = 0.3;
    s.heading_rad = 0.0;  // down the flight: +x
    return s;
}

/// Points on a 2 cm grid over x in [x0, x1), |y| < 1, at height z(x) (the first-edge test's
/// window is 0.03-0.6 m in front of the edge, the middle 70 % of its length).
void addSurface(PointCloud& cloud, double x0, double x1, const std::function<double(double)>& z) {
    for (double x = x0 + 0.005; x < x1; x += 0.02)
        for (double y = -0.99; y < 1.0; y += 0.02)
            cloud.emplace_back(static_cast<float>(x), static_cast<float>(y),
                               static_cast<float>(z(x)));
}

TEST(DescentStart, ALandingOneStepDownIsLevel) {
    // The floor to x = 1.0, one step down to a landing 0.4 m deep, the flight from x = 1.4.
    PointCloud cloud;
    addSurface(cloud, 0.3, 1.0, [](double) { return kFloorZ; });
    addSurface(cloud, 1.0, 1.4, [](double) { return kFloorZ - kRise; });
    const Staircase s =
        descent({{1.4, kFloorZ - kRise}, {1.7, kFloorZ - 2 * kRise}, {2.0, kFloorZ - 3 * kRise}});
    EXPECT_FALSE(descentStartsOnASlope(cloud, s, kFloorZ));
}

TEST(DescentStart, ARampUpToTheFloorIsASlope) {
    // A 12 deg ramp from the floor's edge at x = 1.0 down; its "edges" are ring lines on it.
    const double grade = std::tan(12.0 * M_PI / 180.0);
    const auto ramp = [&](double x) { return kFloorZ - grade * (x - 1.0); };
    PointCloud cloud;
    addSurface(cloud, 0.3, 1.0, [](double) { return kFloorZ; });
    addSurface(cloud, 1.0, 3.0, ramp);
    Staircase s = descent({{1.8, ramp(1.8)}, {2.3, ramp(2.3)}, {2.8, ramp(2.8)}});
    s.step_height = ramp(1.8) - ramp(2.3);  // 0.106 m
    EXPECT_TRUE(descentStartsOnASlope(cloud, s, kFloorZ));
    // ... but not with the test's bound at 1 (every point may lie off the levels)
    DescentStartParams lenient;
    lenient.max_off_level_fraction = 1.0;
    EXPECT_FALSE(descentStartsOnASlope(cloud, s, kFloorZ, lenient));
}

TEST(DescentStart, OnlyDescentsBelowTheFloorWithEnoughPointsAreAsked) {
    const double grade = std::tan(12.0 * M_PI / 180.0);
    const auto ramp = [&](double x) { return kFloorZ - grade * (x - 1.0); };
    PointCloud cloud;
    addSurface(cloud, 1.0, 3.0, ramp);
    Staircase s = descent({{1.8, ramp(1.8)}, {2.3, ramp(2.3)}, {2.8, ramp(2.8)}});
    s.step_height = ramp(1.8) - ramp(2.3);
    ASSERT_TRUE(descentStartsOnASlope(cloud, s, kFloorZ));
    Staircase up = s;  // an ascending flight is never asked
    up.direction = StairDirection::Ascending;
    EXPECT_FALSE(descentStartsOnASlope(cloud, up, kFloorZ));
    // a first edge on the floor: the floor lies in front of it
    EXPECT_FALSE(descentStartsOnASlope(cloud, s, ramp(1.8) + 0.02));
    // too few points in front of the first edge: no verdict
    PointCloud sparse;
    for (std::size_t i = 0; i < cloud.size(); i += 200) sparse.push_back(cloud[i]);
    EXPECT_FALSE(descentStartsOnASlope(sparse, s, kFloorZ));
    // non-finite points are ignored, the verdict stands
    const float nan = std::numeric_limits<float>::quiet_NaN();
    cloud.emplace_back(nan, 0.f, -0.6f);
    cloud.emplace_back(1.5f, 0.f, nan);
    cloud.emplace_back(std::numeric_limits<float>::infinity(), 0.f, -0.6f);
    EXPECT_TRUE(descentStartsOnASlope(cloud, s, kFloorZ));
    // an empty cloud: no verdict
    EXPECT_FALSE(descentStartsOnASlope(PointCloud{}, s, kFloorZ));
}

}  // namespace
}  // namespace stairmap
