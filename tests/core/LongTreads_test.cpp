// Deep treads count only where they are seen level: hand-made edges and clouds.
#include "core/LongTreads.h"

#include <gtest/gtest.h>

#include <vector>

#include "support/HandMadeNosing.h"

namespace stairmap {
namespace {

constexpr double kRise = 0.19;  // [m]
constexpr double kRun = 0.55;   // [m] beyond condition 2's 0.45 m

LineSegment nosing(double x, double z) { return test::nosingAcrossY(x, z, 0.6); }

/// Points on a horizontal rectangle x in [x0, x1), y in [-0.6, 0.6] at height z, 3 cm apart.
void addTread(PointCloud& cloud, double x0, double x1, double z) {
    for (double x = x0; x < x1; x += 0.03)
        for (double y = -0.6; y <= 0.6; y += 0.03) cloud.emplace_back(float(x), float(y), float(z));
}

/// Nosings 1..n of a flight rising along +x from x = 1 with the given rise and run.
std::vector<LineSegment> nosings(int n, double rise, double run) {
    std::vector<LineSegment> edges;
    for (int k = 1; k <= n; ++k) edges.push_back(nosing(1.0 + (k - 1) * run, k * rise));
    return edges;
}

TEST(LongTreads, DeepLevelTreadsAreSeenLevel) {
    PointCloud cloud;
    for (int k = 1; k <= 3; ++k) addTread(cloud, 1.0 + (k - 1) * kRun, 1.0 + k * kRun, k * kRise);
    const auto edges = nosings(3, kRise, kRun);
    EXPECT_TRUE(treadsSeenLevel(cloud, edges));
    EXPECT_NEAR(meanRun(edges), kRun, 1e-9);
}

TEST(LongTreads, EveryOtherNosingOfAShallowFlightIsNoDeepTread) {
    // A flight of 0.095 m rises on 0.275 m runs: its nosings 2, 4, 6 look like 0.19 m rises on
    // 0.55 m treads, but the skipped steps' treads lie half-way up between them.
    PointCloud cloud;
    for (int k = 1; k <= 6; ++k)
        addTread(cloud, 1.0 + (k - 1) * 0.5 * kRun, 1.0 + k * 0.5 * kRun, k * 0.5 * kRise);
    std::vector<LineSegment> every_other;
    for (int k = 1; k <= 3; ++k) every_other.push_back(nosing(1.0 + (2 * k - 1) * 0.5 * kRun, k * kRise));
    EXPECT_FALSE(treadsSeenLevel(cloud, every_other));
}

TEST(LongTreads, AnUnseenTreadIsNotLevel) {
    // Only the first tread in the cloud (a LiDAR below the second tread's height sees no tread).
    PointCloud cloud;
    addTread(cloud, 1.0, 1.0 + kRun, kRise);
    EXPECT_FALSE(treadsSeenLevel(cloud, nosings(3, kRise, kRun)));
    EXPECT_FALSE(treadsSeenLevel(PointCloud{}, nosings(3, kRise, kRun)));
}

TEST(LongTreads, ASlopingTreadIsNotLevel) {
    // A stepped ramp: each "tread" climbs most of the way to the next nosing.
    PointCloud cloud;
    for (int k = 1; k <= 3; ++k)
        for (double x = 0.0; x < kRun; x += 0.03)
            for (double y = -0.6; y <= 0.6; y += 0.03)
                cloud.emplace_back(float(1.0 + (k - 1) * kRun + x), float(y),
                                   float(k * kRise + 0.8 * kRise * x / kRun));
    EXPECT_FALSE(treadsSeenLevel(cloud, nosings(3, kRise, kRun)));
}

TEST(LongTreads, ADenseTreadIsSeenDenselyAndARingIsNot) {
    // 3 cm grid: ~1100 points per m^2. One LiDAR ring across each tread: a row of points.
    PointCloud dense, ring;
    for (int k = 1; k <= 3; ++k) {
        addTread(dense, 1.0 + (k - 1) * kRun, 1.0 + k * kRun, k * kRise);
        for (double y = -0.6; y <= 0.6; y += 0.03)
            ring.emplace_back(float(1.0 + (k - 0.5) * kRun), float(y), float(k * kRise));
    }
    LevelTreadParams densely;
    densely.min_points_per_m2 = 400.0;
    const auto edges = nosings(3, kRise, kRun);
    EXPECT_TRUE(treadsSeenLevel(ring, edges));
    EXPECT_FALSE(treadsSeenLevel(ring, edges, densely));
    EXPECT_TRUE(treadsSeenLevel(dense, edges, densely));
}

}  // namespace
}  // namespace stairmap
