// Algorithm 1's chain search on hand-made nosing lines: runs are uniform along a straight flight.
#include "core/StairSearch.h"

#include <gtest/gtest.h>

#include <vector>

#include "support/HandMadeNosing.h"

namespace stairmap {
namespace {

/// A nosing line across y in [-0.5, 0.5] at distance x, height z (its normal along +x).
LineSegment nosing(double x, double z) { return test::nosingAcrossY(x, z, 0.5); }

/// Four nosings 0.17 m apart in height, the first three 0.25 m apart; the fourth `last_run` [m]
/// behind the third. Returns the longest chain found (indices into the lines).
std::vector<int> chainWithLastRun(double last_run) {
    const std::vector<LineSegment> lines = {nosing(1.0, 0.17), nosing(1.25, 0.34),
                                            nosing(1.50, 0.51), nosing(1.50 + last_run, 0.68)};
    DetectorParams p;
    p.min_steps = 3;
    const auto chains = searchStaircases(lines, 0.0, p.floor_tolerance_m, p);
    return chains.empty() ? std::vector<int>{} : chains.front();
}

TEST(StairSearch, AStepWithTheFlightsRunContinuesTheChain) {
    EXPECT_EQ(chainWithLastRun(0.30), (std::vector<int>{0, 1, 2, 3}));  // 1.2x the run
}

TEST(StairSearch, AStepTwiceAsDeepIsNotPartOfTheFlight) {
    // 0.45 m passes Definition 1 on its own (run <= 0.45 m, slope 20.7 deg) but is 1.8x the
    // flight's run: a nosing stepped over with a wrong rise, or another structure.
    EXPECT_EQ(chainWithLastRun(0.45), (std::vector<int>{0, 1, 2}));
}

TEST(StairSearch, AShortFirstPairDoesNotSetTheRunOfTheFlight) {
    // Runs 0.20, 0.28, 0.31, 0.30 m: the first pair reads short (a line near the robot cut
    // short), the third is 1.55x its run but within 1.5x of the chain's median run.
    const std::vector<LineSegment> lines = {nosing(1.0, 0.17), nosing(1.20, 0.34),
                                            nosing(1.48, 0.51), nosing(1.79, 0.68),
                                            nosing(2.09, 0.85)};
    DetectorParams p;
    p.min_steps = 3;
    const auto chains = searchStaircases(lines, 0.0, p.floor_tolerance_m, p);
    ASSERT_EQ(chains.size(), 1u);
    EXPECT_EQ(chains.front(), (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(StairSearch, ARefusedChainComesWithTheOtherChainsAsLong) {
    // The first nosing seen twice: a 0.4 m piece split off at a bend (a little lower, so it sorts
    // first) and its full line. Three edges are one short of min_steps; the chain through the
    // full line is returned beside the refused one, for the continuation tests to try.
    LineSegment piece = test::nosingAcrossY(0.98, 0.165, 0.2);
    piece.start.y() += 0.4;
    piece.end.y() += 0.4;
    const std::vector<LineSegment> lines = {piece, nosing(1.0, 0.17), nosing(1.4, 0.34),
                                            nosing(1.8, 0.51)};
    DetectorParams p;
    std::vector<int> refused;
    std::vector<std::vector<int>> ties;
    const auto chains =
        searchStaircases(lines, 0.0, p.floor_tolerance_m, p, &refused, nullptr, false, &ties);
    EXPECT_TRUE(chains.empty());
    EXPECT_EQ(refused, (std::vector<int>{0, 2, 3}));
    ASSERT_EQ(ties.size(), 1u);
    EXPECT_EQ(ties.front(), (std::vector<int>{1, 2, 3}));
}

// A flight rising from a sunken area below the floor (z = 0), 0.18 m rises, 0.28 m runs: its
// nosing at the floor's height (x = 1.28) is a ground line, never searched. `lines` holds the
// searched ones; the chains found with or without DetectorParams::ascend_from_below_floor.
std::vector<std::vector<int>> searchFromBelow(const std::vector<LineSegment>& lines,
                                              bool ascend_from_below_floor) {
    DetectorParams p;
    p.ascend_from_below_floor = ascend_from_below_floor;
    return searchStaircases(lines, 0.0, p.floor_tolerance_m, p, nullptr, nullptr,
                            /*continue_down=*/true);
}

TEST(StairSearch, ANosingAtTheFloorsHeightSteppedOverCounts) {
    // The chain from the floor (0.18, 0.36) continues down across the floor's height to -0.18;
    // with the nosing stepped over there, the flight has its four edges.
    const std::vector<LineSegment> lines = {nosing(1.0, -0.18), nosing(1.56, 0.18),
                                            nosing(1.84, 0.36)};
    const auto chains = searchFromBelow(lines, true);
    ASSERT_EQ(chains.size(), 1u);
    EXPECT_EQ(chains.front(), (std::vector<int>{0, 1, 2}));
    EXPECT_TRUE(searchFromBelow(lines, false).empty());  // three seen edges are a stage's
}

TEST(StairSearch, AChainFromBelowTheFloorMustRiseAboveIt) {
    // One line above the floor, two below: nothing starts from the floor, so the search starts
    // from the lines below it.
    const std::vector<LineSegment> from_below = {nosing(0.72, -0.36), nosing(1.0, -0.18),
                                                 nosing(1.56, 0.18)};
    const auto chains = searchFromBelow(from_below, true);
    ASSERT_EQ(chains.size(), 1u);
    EXPECT_EQ(chains.front(), (std::vector<int>{0, 1, 2}));
    EXPECT_TRUE(searchFromBelow(from_below, false).empty());
    // Steps that stay below the floor (a pit's, four of them) are no ascending flight.
    const std::vector<LineSegment> pit = {nosing(0.16, -0.72), nosing(0.44, -0.54),
                                          nosing(0.72, -0.36), nosing(1.0, -0.18)};
    EXPECT_TRUE(searchFromBelow(pit, true).empty());
}

TEST(StairSearch, OnlyANosingAtTheFloorsHeightCountsWhenSteppedOver) {
    // 0.2 m rises from the floor, the second nosing (0.4 m) not seen: it could have been, so
    // three seen edges stay one short.
    const std::vector<LineSegment> lines = {nosing(1.0, 0.2), nosing(1.56, 0.6), nosing(1.84, 0.8)};
    EXPECT_TRUE(searchFromBelow(lines, true).empty());
}

}  // namespace
}  // namespace stairmap
