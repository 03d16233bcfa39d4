// Direct tests of the staircase and edge fusion used by the landmark map.
#include <gtest/gtest.h>

#include "map/EdgeFusion.h"
#include "map/StaircaseCanonical.h"
#include "map/StaircaseFusion.h"
#include "SyntheticStairs.h"

namespace stairmap {
namespace {

WeightedStaircase weighted(const Staircase& s) {
    const Staircase c = *canonicalStaircase(s);
    return {c, std::vector<int>(c.steps.size(), 1)};
}

TEST(StaircaseFusion, OverlappingViewsPairStepsByLevelEvenWithXyDrift) {
    test::FlightTruth truth;
    std::mt19937 rng(41);
    test::ViewSpec va;
    va.last = 4;
    test::ViewSpec vb;
    vb.first = 3;
    vb.last = 6;
    vb.drift = {0.15, 0.0, 0.0};  // beyond the Definition-2 distance: no pair matches
    const WeightedStaircase a = weighted(test::makeDetection(truth, va, rng));
    const WeightedStaircase b = weighted(test::makeDetection(truth, vb, rng));
    const WeightedStaircase fused = fuseStaircases(a, b, LandmarkParams{});
    ASSERT_EQ(fused.stairs.steps.size(), 7u);
    for (int i = 0; i < 7; ++i) {
        EXPECT_NEAR(fused.stairs.steps[i].centre().z(), truth.edgeCentre(i).z(), 1e-9);
    }
    EXPECT_EQ(fused.step_observations, (std::vector<int>{1, 1, 1, 2, 2, 1, 1}));
}

TEST(StaircaseFusion, GapBetweenPartialViewsIsKeptAndGeometryStaysRight) {
    test::FlightTruth truth;
    truth.num_steps = 16;
    std::mt19937 rng(42);
    test::ViewSpec bottom;
    bottom.last = 3;
    test::ViewSpec top;
    top.first = 11;
    const WeightedStaircase fused = fuseStaircases(
        weighted(test::makeDetection(truth, bottom, rng)),
        weighted(test::makeDetection(truth, top, rng)), LandmarkParams{});
    ASSERT_EQ(fused.stairs.steps.size(), 9u);  // 4 + 5 seen, 7 never seen stay absent
    EXPECT_NEAR(fused.stairs.step_height, truth.rise, 1e-9);
    EXPECT_NEAR(fused.stairs.step_depth, truth.run, 1e-9);
    EXPECT_NEAR(fused.stairs.steps.back().centre().z(), truth.topZ(), 1e-9);
}

TEST(EdgeFusion, WeightsByCovarianceAndKeepsTheWorldConvention) {
    // Two parallel observations of an edge along y at x = 1: the confident one dominates.
    StairEdge a, b;
    a.start = {1.0, 1.0, 0.2};
    a.end = {1.0, -1.0, 0.2};
    b.start = {1.04, 1.0, 0.2};
    b.end = {1.04, -1.0, 0.2};
    a.cov_rho_theta = Eigen::Vector2d(1e-4, 1e-4).asDiagonal();   // sigma 1 cm
    b.cov_rho_theta = Eigen::Vector2d(9e-4, 1e-4).asDiagonal();   // sigma 3 cm
    const StairEdge f = fuseEdges(a, 1, b, 1, 0.0, LandmarkParams{});
    EXPECT_NEAR(f.centre().x(), 1.0 + 0.04 * 0.1, 1e-6);  // weights 9:1
    EXPECT_GT(f.start.y(), f.end.y());  // start on the left facing uphill (+x)
    EXPECT_NEAR(f.cov_rho_theta(0, 0), 1.0 / (1.0 / 1e-4 + 1.0 / 9e-4), 1e-9);
    EXPECT_NEAR(f.length(), 2.0, 1e-9);
}

TEST(EdgeFusion, LongerObservationExtendsAPartialEdge) {
    StairEdge partial, full;
    partial.start = {0.0, 0.2, 0.0};
    partial.end = {0.0, -0.6, 0.0};
    full.start = {0.0, 0.6, 0.0};
    full.end = {0.0, -0.6, 0.0};
    const StairEdge f = fuseEdges(partial, 5, full, 1, 0.0, LandmarkParams{});
    EXPECT_NEAR(f.start.y(), 0.6, 1e-9);  // beyond the end tolerance: extended
    EXPECT_NEAR(f.end.y(), -0.6, 1e-9);   // within it: averaged (both equal here)
}

}  // namespace
}  // namespace stairmap
