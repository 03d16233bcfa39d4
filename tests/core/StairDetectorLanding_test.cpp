// A flight that rises from a landing one step above the robot's floor, seen as a legged robot's
// elevation map sees it (one point per 3.3 cm cell on the top surface, no vertical faces): the
// real ANYmal entrance of the issue (one step up onto a 1.1 m landing, then the flight) has only
// three rises above its landing. The same three rises straight off the floor are a two-step stage.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "support/DetectionMatching.h"
#include "core/StairDetector.h"
#include "core/StaircaseGeometry.h"

namespace stairmap::test {
namespace {

constexpr double kFloorZ = -0.5;   // [m] the robot's floor in the robot frame
constexpr double kCell = 0.033;    // [m] elevation-map cell
constexpr double kRise = 0.186;    // [m] the entrance's rises
constexpr double kRun = 0.42;      // [m]
constexpr double kFlightX = 2.1;   // [m] the flight's first riser

/// One point per cell over x in [-1, 3.4], y in [-1, 1] at the floor plus h(x) (a 2.5D map: the top
/// surface only, the map's extent ending 0.4 m behind the last nosing).
PointCloud heightField(const std::function<double(double)>& h) {
    PointCloud cloud;
    for (double x = -1.0; x < 3.4; x += kCell)
        for (double y = -1.0; y <= 1.0; y += kCell)
            cloud.emplace_back(float(x), float(y), float(kFloorZ + h(x)));
    return cloud;
}

/// Three rises of kRise from x = kFlightX, kRun apart, above a surface at `base` [m].
double flight(double x, double base) {
    if (x < kFlightX) return base;
    return base + kRise * std::min(3, 1 + static_cast<int>((x - kFlightX) / kRun));
}

TEST(FlightFromARaisedLanding, ThreeRisesAboveALandingOneStepUpAreAFlight) {
    // One 0.10 m step up at x = 1 onto a 1.1 m landing, then the flight.
    const PointCloud cloud = heightField([](double x) { return x < 1.0 ? 0.0 : flight(x, 0.10); });
    const DetectionResult r = StairDetector().detect(cloud, kFloorZ);
    ASSERT_EQ(r.staircases.size(), 1u) << describe(r);
    const Staircase& s = r.staircases.front();
    EXPECT_EQ(s.direction, StairDirection::Ascending);
    EXPECT_EQ(s.steps.size(), 3u);
    EXPECT_NEAR(s.step_height, kRise, 0.01);
    EXPECT_NEAR(s.step_depth, kRun, 0.02);
    EXPECT_NEAR(s.steps.front().centre().x(), kFlightX, 0.05);
    EXPECT_NEAR(flightStartZ(s) - kFloorZ, 0.10, 0.03);
}

TEST(FlightFromARaisedLanding, TheSameRisesOffTheFloorAreAStage) {
    const PointCloud cloud = heightField([](double x) { return flight(x, 0.0); });
    const DetectionResult r = StairDetector().detect(cloud, kFloorZ);
    EXPECT_TRUE(r.staircases.empty()) << describe(r);
}

TEST(FlightFromARaisedLanding, ALandingLowerThanAStepIsTheFloor) {
    // 5 cm up: a threshold or a mat, not a step; the rises above it are still a stage.
    const PointCloud cloud = heightField([](double x) { return x < 1.0 ? 0.0 : flight(x, 0.05); });
    const DetectionResult r = StairDetector().detect(cloud, kFloorZ);
    EXPECT_TRUE(r.staircases.empty()) << describe(r);
}

}  // namespace
}  // namespace stairmap::test
