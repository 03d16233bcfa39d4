// The slope along a flight's nosings (slopeAlongNosings) on synthetic point clouds: a staircase
// (level along its nosings), a ramp crossed off its fall line, a wall beside the treads.
#include "core/NosingSlope.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/HandMadeNosing.h"

namespace stairmap {
namespace {

constexpr double kRise = 0.15, kRun = 0.30, kHalfWidth = 0.6;  // [m]
constexpr int kSteps = 5;

/// Nosing k (0-based) of a flight rising along +x from x = 2 m, z = 0.
LineSegment nosing(int k) { return test::nosingAcrossY(2.0 + k * kRun, k * kRise, kHalfWidth); }

std::vector<LineSegment> flightEdges() {
    std::vector<LineSegment> edges;
    for (int k = 0; k < kSteps; ++k) edges.push_back(nosing(k));
    return edges;
}

/// Points every 2 cm on the treads and risers of that flight.
PointCloud stairPoints() {
    PointCloud cloud;
    for (int k = 0; k < kSteps; ++k)
        for (double y = -kHalfWidth; y <= kHalfWidth; y += 0.02) {
            for (double x = 0.0; x < kRun; x += 0.02)  // tread k behind nosing k
                cloud.emplace_back(2.0 + k * kRun + x, y, k * kRise);
            for (double z = 0.0; z < kRise; z += 0.02)  // riser under nosing k + 1
                cloud.emplace_back(2.0 + (k + 1) * kRun, y, k * kRise + z);
        }
    return cloud;
}

TEST(NosingSlope, AStaircaseIsLevelAlongItsNosings) {
    const auto slope = slopeAlongNosings(stairPoints(), flightEdges());
    ASSERT_TRUE(slope.has_value());
    EXPECT_NEAR(*slope, 0.0, 0.005);
}

TEST(NosingSlope, ARampCrossedOffItsFallLineRisesAlongThem) {
    // A 15 deg ramp whose fall line lies 45 deg off the "flight's" heading: along the pieces it
    // rises tan(15 deg) sin(45 deg) = 0.19 m per m.
    const double grade = std::tan(15.0 * M_PI / 180.0);
    const Eigen::Vector2d fall(std::cos(M_PI / 4), std::sin(M_PI / 4));
    PointCloud cloud;
    for (double x = 1.9; x < 3.4; x += 0.02)
        for (double y = -kHalfWidth; y <= kHalfWidth; y += 0.02)
            cloud.emplace_back(x, y, grade * fall.dot(Eigen::Vector2d(x - 2.0, y)));
    const auto slope = slopeAlongNosings(cloud, flightEdges());
    ASSERT_TRUE(slope.has_value());
    EXPECT_NEAR(*slope, grade * fall.y(), 0.01);
}

TEST(NosingSlope, AWallBesideTheTreadsIsLeftOut) {
    // A wall along the flight's left end, as many points as the steps have: the first fit tilts
    // towards it, the refits leave most of it out (the band of it near the treads' heights stays).
    PointCloud cloud = stairPoints();
    for (double x = 2.0; x < 2.0 + kSteps * kRun; x += 0.02)
        for (double z = 0.0; z < kSteps * kRise + kRise; z += 0.02)
            cloud.emplace_back(x, kHalfWidth - 0.01, z);
    NosingSlopeParams one_fit;
    one_fit.refits = 0;
    const auto tilted = slopeAlongNosings(cloud, flightEdges(), one_fit);
    const auto slope = slopeAlongNosings(cloud, flightEdges());
    ASSERT_TRUE(tilted.has_value());
    ASSERT_TRUE(slope.has_value());
    EXPECT_GT(std::abs(*tilted), 0.1);
    EXPECT_LT(std::abs(*slope), 0.06);
}

TEST(NosingSlope, TooFewPointsMeasureNothing) {
    PointCloud cloud = {{2.1f, 0.0f, 0.0f}, {2.4f, 0.3f, 0.15f}, {2.7f, -0.3f, 0.3f}};
    EXPECT_FALSE(slopeAlongNosings(cloud, flightEdges()).has_value());
    cloud.emplace_back(std::nanf(""), 0.0f, 0.0f);
    EXPECT_FALSE(slopeAlongNosings(cloud, flightEdges()).has_value());
}

}  // namespace
}  // namespace stairmap
