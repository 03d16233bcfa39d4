// A descending flight seen down to the end of the view: a legged robot's elevation map cropped
// mid-way down its third tread shows the floor's edge and two nosings below it, too few for
// min_steps. It counts because nothing at all is mapped one step beyond its lowest nosing; the
// same two steps into a pit, whose floor is mapped there, are no flight.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/StairDetector.h"
#include "support/HeightField.h"

namespace stairmap::test {
namespace {

constexpr double kFloorZ = -0.5;    // [m] the robot's floor in the robot frame
constexpr double kCell = 0.03;      // [m] elevation-map cell
constexpr double kRise = 0.17;      // [m]
constexpr double kRun = 0.30;       // [m]
constexpr double kTopX = 2.0;       // [m] the floor's edge, the flight going down along +x
constexpr double kHalfWidth = 0.6;  // [m] the flight's half width; the floor beside it

/// The floor with a flight cut into it (|y| < kHalfWidth) from kTopX down along +x: tread k
/// (k = 1, 2, ...) spans [kTopX + (k - 1) run, kTopX + k run) at k rises below the floor, down
/// to `levels` rises (a pit's floor from there on). The map ends at `map_end` (unmapped beyond).
PointCloud flightDown(int levels, double map_end) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return heightField(
        [&](double x, double y) {
            if (x >= map_end) return nan;
            if (x < kTopX || std::abs(y) >= kHalfWidth) return kFloorZ;
            const int k = std::min(levels, 1 + static_cast<int>((x - kTopX) / kRun));
            return kFloorZ - k * kRise;
        },
        -1.0, 6.0, 1.5, kCell);
}

int descendingFlights(const PointCloud& cloud) {
    int n = 0;
    for (const Staircase& s : StairDetector().detect(cloud, kFloorZ).staircases)
        n += s.direction == StairDirection::Descending;
    return n;
}

TEST(DescentToTheViewEnd, TwoNosingsBelowTheFloorEdgeCountWhereTheMapEnds) {
    // Cropped a third of the way into the third tread (as an elevation map's +-4 m crop).
    const PointCloud cloud = flightDown(10, kTopX + 2 * kRun + 0.1);
    const auto result = StairDetector().detect(cloud, kFloorZ);
    ASSERT_EQ(result.staircases.size(), 1u);
    const Staircase& s = result.staircases.front();
    EXPECT_EQ(s.direction, StairDirection::Descending);
    EXPECT_NEAR(s.step_height, kRise, 0.01);
    EXPECT_NEAR(s.step_depth, kRun, 0.03);
    ASSERT_FALSE(s.steps.empty());
    EXPECT_NEAR(s.steps.front().centre().x(), kTopX, 0.05);  // the floor's edge first
    EXPECT_NEAR(s.steps.front().centre().z(), kFloorZ, 0.02);
}

TEST(DescentToTheViewEnd, TwoStepsIntoAPitWhoseFloorIsMappedAreNoFlight) {
    // Two steps down, then the pit's floor three rises down, mapped for 2 m beyond the second
    // step's nosing: the same floor edge and two nosings as the cropped view.
    EXPECT_EQ(descendingFlights(flightDown(3, kTopX + 2 * kRun + 2.0)), 0);
}

TEST(DescentToTheViewEnd, AThirdStepMappedBeyondIsNoViewEnd) {
    // The map reaches the third tread's far half and the fourth: the flight is seen going on, so
    // its chain is Algorithm 1's own (four edges with the floor's), found either way.
    EXPECT_EQ(descendingFlights(flightDown(10, kTopX + 4 * kRun + 0.1)), 1);
}

}  // namespace
}  // namespace stairmap::test
