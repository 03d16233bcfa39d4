// Ring-aliased flights (DetectorParams::max_double_step_rise_m): a chain of pairs two steps apart
// gets its skipped nosings back, but only where its treads are not seen level. A real flight of
// deep level treads with rises in the pairs' range stays as it is, reported once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/StairDetector.h"

namespace stairmap {
namespace {

constexpr double kFloorZ = -0.5;  // [m] the robot's floor in the robot frame
constexpr double kCell = 0.03;    // [m] elevation-map cell: the treads are seen densely
constexpr double kFlightX = 2.0;  // [m] the first riser

/// One point per cell on the top surface of `risers` rises of `rise` every `run` from kFlightX
/// (a legged robot's elevation map), y in [-1, 1].
PointCloud flightMap(int risers, double rise, double run) {
    PointCloud cloud;
    const double x_max = kFlightX + risers * run + 1.0;
    for (double x = -1.0; x < x_max; x += kCell)
        for (double y = -1.0; y <= 1.0; y += kCell) {
            const int k =
                x < kFlightX ? 0 : std::min(risers, 1 + static_cast<int>((x - kFlightX) / run));
            cloud.emplace_back(float(x), float(y), float(kFloorZ + k * rise));
        }
    return cloud;
}

TEST(TwoStepPairs, DeepLevelTreadsInThePairsRangeAreNotSplit) {
    // 0.24 m rises on 0.60 m treads: as pairs of a 0.12 / 0.30 flight they would pass, but every
    // tread is seen level (an outdoor flight's, a terrace's), so no nosing is put back between.
    const double rise = 0.24, run = 0.60;
    DetectorParams p;
    ASSERT_GE(rise, 2 * p.min_step_height_m);
    ASSERT_LE(rise, p.max_double_step_rise_m);
    ASSERT_GT(run, p.max_step_depth_m);
    const DetectionResult r = StairDetector(p).detect(flightMap(5, rise, run), kFloorZ);
    ASSERT_EQ(r.staircases.size(), 1u);
    EXPECT_NEAR(r.staircases[0].step_height, rise, 0.02);
    EXPECT_NEAR(r.staircases[0].step_depth, run, 0.03);
}

TEST(TwoStepPairs, OffTheSearchForPairsFindsNothingNew) {
    // The parameter's off value leaves the deep flight to the deep-tread search alone.
    DetectorParams p;
    p.max_double_step_rise_m = 0.0;
    const DetectionResult r = StairDetector(p).detect(flightMap(5, 0.24, 0.60), kFloorZ);
    ASSERT_EQ(r.staircases.size(), 1u);
    EXPECT_NEAR(r.staircases[0].step_height, 0.24, 0.02);
}

}  // namespace
}  // namespace stairmap
