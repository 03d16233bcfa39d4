// Nosings the chain search stepped over are put back (fillMissingNosings), from hand-made edges.
#include "core/MissingNosings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/HandMadeNosing.h"

namespace stairmap {
namespace {

constexpr double kRise = 0.125;  // [m]
constexpr double kRun = 0.25;    // [m]

/// A nosing across y in [-0.6, 0.6] at distance x, height z, seen (20 points).
LineSegment nosing(double x, double z) { return test::nosingAcrossY(x, z, 0.6); }

/// The edges of a flight (kRise, kRun) at the given step indices.
std::vector<LineSegment> edgesAtSteps(const std::vector<int>& steps) {
    std::vector<LineSegment> edges;
    for (int k : steps) edges.push_back(nosing(1.0 + k * kRun, k * kRise));
    return edges;
}

TEST(MissingNosings, OneSkippedNosingIsPutBackHalfway) {
    std::vector<LineSegment> edges = edgesAtSteps({0, 1, 2, 4, 5});
    EXPECT_EQ(fillMissingNosings(edges), 1);
    ASSERT_EQ(edges.size(), 6u);
    EXPECT_EQ(edges[3].num_points, 0);
    EXPECT_NEAR(edges[3].z, 3 * kRise, 1e-9);
    EXPECT_NEAR(edges[3].centre().x(), 1.0 + 3 * kRun, 1e-9);
}

TEST(MissingNosings, AChainSkippingMostOtherNosingsGetsEveryStepBack) {
    // A far ring-aliased view (dev2 r0223): pairs 1, 2, 1, 2, 2 steps apart. The median pair is
    // two steps, so the median rise alone reads the flight at twice its rise and puts nothing back.
    std::vector<LineSegment> edges = edgesAtSteps({0, 1, 3, 4, 6, 8});
    EXPECT_EQ(fillMissingNosings(edges), 3);
    ASSERT_EQ(edges.size(), 9u);
    for (std::size_t k = 0; k < edges.size(); ++k) {
        EXPECT_NEAR(edges[k].z, k * kRise, 1e-9) << "edge " << k;
        EXPECT_NEAR(edges[k].centre().x(), 1.0 + k * kRun, 1e-9) << "edge " << k;
    }
}

TEST(MissingNosings, AnAliasedChainWithOneRiserHitReadLowStillGetsEveryStepBack) {
    // dev r0192: pairs 1, 2, 2, 1 steps apart; the last pair's lower edge is a riser hit read 4.5
    // cm low, so that one-step pair rises 1.4 steps (neither one nor two), but its spacing is one
    // run.
    std::vector<LineSegment> edges = edgesAtSteps({0, 1, 3, 5, 6});
    edges[3].z -= 0.045;
    EXPECT_EQ(fillMissingNosings(edges, 0.11), 2);
    ASSERT_EQ(edges.size(), 7u);
    for (std::size_t k = 0; k < edges.size(); ++k)
        EXPECT_NEAR(edges[k].centre().x(), 1.0 + k * kRun, 1e-9) << "edge " << k;
}

TEST(MissingNosings, AnAliasedChainWhoseFirstLineIsAShortTurnedPieceGetsEveryStepBack) {
    // dev6 r0026 (a level VLP-16 5.9 m from an open-riser flight): pairs 1, 2, 2, 2, 2, 1, 2 steps
    // apart, the lowest nosing seen as a 0.5 m piece turned 30 deg. The pair's spacing measured
    // from the turned piece's line alone read two thirds of a run (no step, no unit rise: nothing
    // was put back and the chain read 1.6 times the rise); both ways it reads a step.
    std::vector<LineSegment> edges = edgesAtSteps({0, 1, 3, 5, 7, 9, 10, 12});
    const double turn = 30.0 * M_PI / 180.0;
    const Eigen::Vector2d centre(1.0, 0.1), along(-std::sin(turn), std::cos(turn));
    edges[0] = unseenNosing(centre - 0.25 * along, centre + 0.25 * along, 0.0);
    edges[0].num_points = 8;
    EXPECT_EQ(fillMissingNosings(edges), 5);
    ASSERT_EQ(edges.size(), 13u);
    for (std::size_t k = 1; k < edges.size(); ++k)
        EXPECT_NEAR(edges[k].z, k * kRise, 1e-9) << "edge " << k;
}

TEST(MissingNosings, AnEdgeReadLowIsNoReasonToSplitTheOtherSteps) {
    // Evenly spaced nosings where the last riser hit reads 7 cm low: its rise alone looks like one
    // step of a flight with 0.10 m rises, the others two of them; but its spacing is a full run,
    // so no step is put back anywhere.
    std::vector<LineSegment> edges;
    const double rise = 0.17, run = 0.28;
    for (int k = 0; k < 6; ++k) edges.push_back(nosing(1.0 + k * run, k * rise));
    edges[5].z -= 0.07;  // pairs: 0.17, 0.17, 0.17, 0.17, 0.10 m
    EXPECT_EQ(fillMissingNosings(edges), 0);
    EXPECT_EQ(edges.size(), 6u);
}

/// Edges one run apart (0.24 m) at the given heights, `half` metres either side of the axis.
std::vector<LineSegment> evenlySpacedAt(const std::vector<double>& z, double half) {
    std::vector<LineSegment> edges;
    for (std::size_t k = 0; k < z.size(); ++k)
        edges.push_back(test::nosingAcrossY(1.0 + 0.24 * k, z[k], half));
    return edges;
}

TEST(MissingNosings, RiserHitsBelowABuildingCodeRiseAreNotSplitWhereTheSpacingIsOneRun) {
    // A far LiDAR's riser hits read low by up to a ring spacing (dev2 r0151, r0170): typical pairs
    // 7-8 cm apart, under condition 1's 0.11 m, one 15.6 cm. That pair is one run apart like the
    // others: one step read high against its neighbours, not two steps (putting one back made
    // the flight's rise 8.3 cm for 10.4 cm).
    const std::vector<double> z = {0.0, 0.07, 0.226, 0.306, 0.386};
    std::vector<LineSegment> short_pieces = evenlySpacedAt(z, 0.3);
    EXPECT_EQ(fillMissingNosings(short_pieces, 0.11), 0);
    EXPECT_EQ(short_pieces.size(), 5u);
    // without condition 1's bound the heights alone decide (two steps there)
    std::vector<LineSegment> unbounded = evenlySpacedAt(z, 0.3);
    EXPECT_EQ(fillMissingNosings(unbounded), 1);
}

TEST(MissingNosings, LongEdgesOneRunApartAreOneStepWhateverTheirHeights) {
    // Plausible rises, one pair twice as high but one run apart. Long edges (1.2 m) pin their
    // spacing well: one step whose lower edge is a riser hit read low (dev2 r0098).
    const std::vector<double> z = {0.0, 0.17, 0.34, 0.68, 0.85};
    std::vector<LineSegment> long_edges = evenlySpacedAt(z, 0.6);
    EXPECT_EQ(fillMissingNosings(long_edges, 0.11), 0);
    // Short far pieces (0.6 m) scatter in direction, their spacing is no better than their
    // heights: the heights decide (dev2 r0087, a skipped nosing whose pair measured one run).
    std::vector<LineSegment> short_pieces = evenlySpacedAt(z, 0.3);
    EXPECT_EQ(fillMissingNosings(short_pieces, 0.11), 1);
}

TEST(MissingNosings, EveryOtherNosingIsPutBackWhereNoLineWasSeen) {
    // A far LiDAR whose rings alias with the steps sees nosings 0, 2, 4, 6 only.
    std::vector<LineSegment> edges = edgesAtSteps({0, 2, 4, 6});
    const std::vector<LineSegment> lines = edges;  // all the lines found near the flight
    ASSERT_TRUE(putBackEveryOtherNosing(lines, edges));
    ASSERT_EQ(edges.size(), 7u);
    for (std::size_t k = 0; k < edges.size(); ++k) {
        EXPECT_NEAR(edges[k].z, k * kRise, 1e-9) << "edge " << k;
        EXPECT_NEAR(edges[k].centre().x(), 1.0 + k * kRun, 1e-9) << "edge " << k;
        EXPECT_EQ(edges[k].num_points == 0, k % 2 == 1) << "edge " << k;
    }
}

TEST(MissingNosings, NoNosingIsPutBackWhereALineWasSeen) {
    // Nosing 3 was found (a piece 0.4 m long, 2 cm off), the search merely stepped over it.
    std::vector<LineSegment> edges = edgesAtSteps({0, 2, 4, 6});
    std::vector<LineSegment> lines = edges;
    lines.push_back(test::nosingAcrossY(1.0 + 3 * kRun + 0.02, 3 * kRise - 0.01, 0.2));
    EXPECT_FALSE(putBackEveryOtherNosing(lines, edges));
    EXPECT_EQ(edges.size(), 4u);
}

// A far level LiDAR's rings hit the risers above it (dev3 r0288: a VLP-16 7.4 m from 0.20 m rises
// on 0.225 m runs): the chain's lines stand on steps 0, 1, 4, 6 and 7, but their heights step by
// the rings' spacing, so by height they read as levels 0, 1, 3, 4, 5 (0.27 m rises).
constexpr double kAliasedRun = 0.225;  // [m]
const std::vector<int> kAliasedSteps = {0, 1, 4, 6, 7};
const std::vector<double> kAliasedHeights = {-0.40, -0.15, 0.38, 0.69, 0.99};  // [m]

std::vector<LineSegment> ringAliasedChain(double dz = 0.0) {
    std::vector<LineSegment> edges;
    for (std::size_t i = 0; i < kAliasedSteps.size(); ++i)
        edges.push_back(nosing(7.0 + kAliasedSteps[i] * kAliasedRun, kAliasedHeights[i] + dz));
    return edges;
}

TEST(NosingsBySpacing, RiserHitsAboveTheSensorAreLevelledByTheirSpacing) {
    std::vector<LineSegment> edges = ringAliasedChain();
    EXPECT_EQ(fillNosingsBySpacing(edges), 3);
    ASSERT_EQ(edges.size(), 8u);
    for (int k = 0; k < 8; ++k) {
        const bool seen =
            std::find(kAliasedSteps.begin(), kAliasedSteps.end(), k) != kAliasedSteps.end();
        EXPECT_EQ(edges[k].num_points > 0, seen) << "level " << k;
        EXPECT_NEAR(edges[k].centre().x(), 7.0 + k * kAliasedRun, 1e-9) << "level " << k;
    }
    EXPECT_NEAR(edges[4].z, 0.38, 1e-9);  // seen edges keep their heights
    // by height alone one nosing is put back, in the 0.53 m pair: levels 0, 1, 3, 4, 5
    std::vector<LineSegment> by_height = ringAliasedChain();
    EXPECT_EQ(fillMissingNosings(by_height), 1);
}

TEST(NosingsBySpacing, HeightsSeenFromAboveDecide) {
    // the same chain below the robot frame's origin: a LiDAR sees those treads from above, an
    // elevation map every height; the heights' levels stand
    std::vector<LineSegment> below = ringAliasedChain(-1.5);
    EXPECT_EQ(fillNosingsBySpacing(below), 0);
    EXPECT_EQ(below.size(), 5u);
}

TEST(NosingsBySpacing, ChainsTheSpacingDoesNotLevelAreLeft) {
    // lines one run apart each: the heights' business (fillMissingNosings)
    std::vector<LineSegment> consecutive;
    for (int k = 0; k < 5; ++k) consecutive.push_back(nosing(7.0 + k * kAliasedRun, 0.3 * k));
    EXPECT_EQ(fillNosingsBySpacing(consecutive), 0);
    // four edges pin no run
    std::vector<LineSegment> four = ringAliasedChain();
    four.pop_back();
    EXPECT_EQ(fillNosingsBySpacing(four), 0);
    // a turning chain (a spiral's wedges, 8 deg per edge): its spacings are no comb
    std::vector<LineSegment> turning = ringAliasedChain();
    for (std::size_t i = 0; i < turning.size(); ++i) {
        const double a = 8.0 * i * M_PI / 180.0;
        const Eigen::Vector2d c = turning[i].centre(), u(-std::sin(a), std::cos(a));
        turning[i].start = c - 0.6 * u;
        turning[i].end = c + 0.6 * u;
        turning[i].theta = a;
    }
    EXPECT_EQ(fillNosingsBySpacing(turning), 0);
    // most pairs two runs apart: a comb of half the run holds any chain
    std::vector<LineSegment> wide;
    for (int k : {0, 2, 4, 6, 7}) wide.push_back(nosing(7.0 + k * kAliasedRun, 0.5 + 0.2 * k));
    EXPECT_EQ(fillNosingsBySpacing(wide), 0);
}

}  // namespace
}  // namespace stairmap
