// A flight that rises from a landing one step above the robot's floor, seen as a legged robot's
// elevation map sees it (one point per 3.3 cm cell on the top surface, no vertical faces): the
// real ANYmal entrance of the issue (one step up onto a 1.1 m landing, then the flight) has only
// three rises above its landing. The same three rises straight off the floor are a two-step stage.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/StairDetector.h"
#include "core/StaircaseGeometry.h"
#include "support/DetectionMatching.h"
#include "support/HeightField.h"

namespace stairmap::test {
namespace {

constexpr double kFloorZ = -0.5;   // [m] the robot's floor in the robot frame
constexpr double kCell = 0.033;    // [m] elevation-map cell
constexpr double kRise = 0.186;    // [m] the entrance's rises
constexpr double kRun = 0.42;      // [m] within condition 2's bound (0.45 m)
constexpr double kDeepRun = 0.58;  // [m] the entrance's treads read with 4 cm cells
constexpr double kFlightX = 2.1;   // [m] the flight's first riser

/// One point per cell over x in [-1, x_max), y in [-1, 1] at the floor plus h(x) (a 2.5D map: the
/// top surface only; nothing mapped beyond x_max).
PointCloud heightField(const std::function<double(double)>& h, double x_max = 4.0) {
    return test::heightField([&](double x, double) { return kFloorZ + h(x); }, -1.0, x_max, 1.0,
                             kCell);
}

/// Three rises of kRise from x = kFlightX, `run` apart, above a surface at `base` [m].
double flight(double x, double base, double run = kRun) {
    if (x < kFlightX) return base;
    return base + kRise * std::min(3, 1 + static_cast<int>((x - kFlightX) / run));
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

TEST(FlightFromARaisedLanding, IsFoundWithTheOptionalSearchesSwitchedOff) {
    // Deep treads and pairs two steps apart off (a valid config): the chain one edge short is
    // still continued from its landing, without the lines-used record those searches keep.
    DetectorParams p;
    p.max_level_tread_depth_m = p.max_step_depth_m;
    p.max_double_step_rise_m = 0.0;
    const PointCloud cloud = heightField([](double x) { return x < 1.0 ? 0.0 : flight(x, 0.10); });
    const DetectionResult r = StairDetector(p).detect(cloud, kFloorZ);
    ASSERT_EQ(r.staircases.size(), 1u) << describe(r);
    EXPECT_EQ(r.staircases.front().steps.size(), 3u);
    EXPECT_NEAR(r.staircases.front().step_height, kRise, 0.01);
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

TEST(FlightFromARaisedLanding, DeepTreadsSeenLevelCount) {
    // The entrance read with 4 cm cells: 0.58 m treads (beyond condition 2's 0.45 m) and a slope
    // of 17.8 deg (below condition 3's 20 deg), each tread seen level from nosing to riser.
    const auto entrance = [](double x) { return x < 1.0 ? 0.0 : flight(x, 0.10, kDeepRun); };
    const PointCloud cloud = heightField(entrance);
    const DetectionResult r = StairDetector().detect(cloud, kFloorZ);
    ASSERT_EQ(r.staircases.size(), 1u) << describe(r);
    EXPECT_EQ(r.staircases.front().steps.size(), 3u);
    EXPECT_NEAR(r.staircases.front().step_height, kRise, 0.01);
    EXPECT_NEAR(r.staircases.front().step_depth, kDeepRun, 0.02);
    // Without the deep-tread search the same cloud gives nothing.
    DetectorParams p;
    p.max_level_tread_depth_m = 0.0;
    const DetectionResult off = StairDetector(p).detect(cloud, kFloorZ);
    EXPECT_TRUE(off.staircases.empty()) << describe(off);
}

/// The map ends this far behind the flight's last nosing (the entrance's top tread is mapped for
/// 10-12 cells, then unknown).
constexpr double kTopSeen = 0.35;  // [m]

TEST(FlightFromARaisedLanding, SeenFromItsLandingDeepTreadsUpToAnUnmappedTopAreAFlight) {
    // The robot on the landing: three rises off its own floor, treads 0.58 m, the top unmapped.
    const double end = kFlightX + 2 * kDeepRun + kTopSeen;
    const PointCloud cloud = heightField([](double x) { return flight(x, 0.0, kDeepRun); }, end);
    const DetectionResult r = StairDetector().detect(cloud, kFloorZ);
    ASSERT_EQ(r.staircases.size(), 1u) << describe(r);
    EXPECT_EQ(r.staircases.front().steps.size(), 3u);
    EXPECT_NEAR(r.staircases.front().step_depth, kDeepRun, 0.02);
    EXPECT_NEAR(flightStartZ(r.staircases.front()) - kFloorZ, 0.0, 0.03);
}

TEST(FlightFromARaisedLanding, DeepTiersUpToASeenPlatformAreAStage) {
    // The same tiers with the platform mapped 1.5 m deep behind them.
    const double end = kFlightX + 2 * kDeepRun + 1.5;
    const PointCloud cloud = heightField([](double x) { return flight(x, 0.0, kDeepRun); }, end);
    const DetectionResult r = StairDetector().detect(cloud, kFloorZ);
    EXPECT_TRUE(r.staircases.empty()) << describe(r);
}

TEST(FlightFromARaisedLanding, IndoorDepthTiersUpToAnUnmappedTopAreAStage) {
    // 0.30 m tiers, the top unmapped: as deep as an indoor flight's treads and a stage's tiers,
    // nothing tells the two apart; no flight.
    const double end = kFlightX + 2 * 0.30 + kTopSeen;
    const PointCloud cloud = heightField([](double x) { return flight(x, 0.0, 0.30); }, end);
    const DetectionResult r = StairDetector().detect(cloud, kFloorZ);
    EXPECT_TRUE(r.staircases.empty()) << describe(r);
}

}  // namespace
}  // namespace stairmap::test
