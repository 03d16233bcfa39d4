// Two turning flights that are pieces of one spiral are joined; pieces of different spirals, or
// not continuing one helix, are not.
#include "core/SpiralPieces.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/StaircaseGeometry.h"

namespace stairmap {
namespace {

constexpr double kRise = 0.15, kStepDeg = 25.0, kInner = 0.15, kOuter = 1.0;

/// Levels [first, last] of a counter-clockwise spiral about `axis` (radial nosings, level 0 at
/// z = kRise), as one ascending flight.
Staircase spiralPiece(int first, int last, Eigen::Vector2d axis = {3.0, 1.0},
                      double turn_sign = 1.0) {
    Staircase s;
    for (int k = first; k <= last; ++k) {
        const double a = turn_sign * k * kStepDeg * M_PI / 180.0;
        const Eigen::Vector2d u(std::cos(a), std::sin(a));
        StairEdge e;
        e.start << axis + kInner * u, kRise * (k + 1);
        e.end << axis + kOuter * u, kRise * (k + 1);
        e.num_points = 20;
        s.steps.push_back(e);
    }
    estimateGeometry(s);
    return s;
}

TEST(SpiralPieces, ConsecutivePiecesAreJoinedIntoOneFlight) {
    std::vector<Staircase> flights = {spiralPiece(5, 9), spiralPiece(0, 4)};
    EXPECT_EQ(joinSpiralPieces(flights), 1);
    ASSERT_EQ(flights.size(), 1u);
    ASSERT_EQ(flights[0].steps.size(), 10u);
    for (std::size_t k = 0; k < 10; ++k)
        EXPECT_NEAR(flights[0].steps[k].start.z(), kRise * (k + 1), 1e-9);
    EXPECT_NEAR(flights[0].step_height, kRise, 1e-6);
}

TEST(SpiralPieces, OneLevelMissingBetweenIsPutBack) {
    std::vector<Staircase> flights = {spiralPiece(0, 4), spiralPiece(6, 10)};
    EXPECT_EQ(joinSpiralPieces(flights), 1);
    ASSERT_EQ(flights.size(), 1u);
    ASSERT_EQ(flights[0].steps.size(), 11u);
    const StairEdge& put_back = flights[0].steps[5];
    EXPECT_EQ(put_back.num_points, 0);
    EXPECT_NEAR(put_back.start.z(), kRise * 6, 1e-9);
}

TEST(SpiralPieces, PiecesOfOtherSpiralsOrOffTheHelixStayApart) {
    // another axis 0.5 m away
    std::vector<Staircase> other_axis = {spiralPiece(0, 4), spiralPiece(5, 9, {3.5, 1.0})};
    EXPECT_EQ(joinSpiralPieces(other_axis), 0);
    EXPECT_EQ(other_axis.size(), 2u);
    // three levels missing between
    std::vector<Staircase> far_above = {spiralPiece(0, 4), spiralPiece(8, 12)};
    EXPECT_EQ(joinSpiralPieces(far_above), 0);
    // the upper piece one level higher but not turned on by a step (a straight piece's place)
    Staircase turned_back = spiralPiece(5, 9);
    for (StairEdge& e : turned_back.steps) {  // rotate the whole piece back by three steps
        const double a = -3 * kStepDeg * M_PI / 180.0;
        for (Eigen::Vector3d* p : {&e.start, &e.end}) {
            const Eigen::Vector2d r = p->head<2>() - Eigen::Vector2d(3.0, 1.0);
            p->head<2>() = Eigen::Vector2d(3.0, 1.0) +
                           Eigen::Vector2d(std::cos(a) * r.x() - std::sin(a) * r.y(),
                                           std::sin(a) * r.x() + std::cos(a) * r.y());
        }
    }
    estimateGeometry(turned_back);
    std::vector<Staircase> off_helix = {spiralPiece(0, 4), turned_back};
    EXPECT_EQ(joinSpiralPieces(off_helix), 0);
    // turning the other way
    std::vector<Staircase> other_turn = {spiralPiece(0, 4), spiralPiece(5, 9, {3.0, 1.0}, -1.0)};
    EXPECT_EQ(joinSpiralPieces(other_turn), 0);
}

// A level LiDAR's riser hits put a spiral's upper levels at the rings' heights: the upper piece
// lies on the lower one's axis, turn and step angle, but not on its helix, and is not joined.
TEST(SpiralPieces, AnUpperPieceOffTheHelixIsDroppedAndTheFootKept) {
    Staircase riser_hits = spiralPiece(8, 13);  // levels 5-7 unseen
    for (StairEdge& e : riser_hits.steps) {     // read 4-16 cm low, as rings do
        const double low = 0.04 + 0.02 * (&e - riser_hits.steps.data());
        e.start.z() -= low;
        e.end.z() -= low;
    }
    estimateGeometry(riser_hits);
    std::vector<Staircase> flights = {riser_hits, spiralPiece(0, 4)};  // upper one listed first
    ASSERT_EQ(joinSpiralPieces(flights), 0);
    EXPECT_EQ(dropSpiralRepeats(flights), 1);
    ASSERT_EQ(flights.size(), 1u);
    ASSERT_EQ(flights[0].steps.size(), 5u);
    EXPECT_NEAR(flights[0].steps.front().start.z(), kRise, 1e-9);
}

TEST(SpiralPieces, FlightsOfOtherSpiralsOrStraightOnesAreNoRepeats) {
    std::vector<Staircase> other_axis = {spiralPiece(0, 4), spiralPiece(8, 12, {3.5, 1.0})};
    EXPECT_EQ(dropSpiralRepeats(other_axis), 0);
    EXPECT_EQ(other_axis.size(), 2u);
    std::vector<Staircase> other_turn = {spiralPiece(0, 4), spiralPiece(8, 12, {3.0, 1.0}, -1.0)};
    EXPECT_EQ(dropSpiralRepeats(other_turn), 0);
    Staircase straight;  // five parallel nosings above the spiral's axis
    for (int k = 0; k < 5; ++k) {
        StairEdge e;
        e.start << 3.0 + 0.3 * k, 0.5, 1.0 + kRise * k;
        e.end << 3.0 + 0.3 * k, 1.5, 1.0 + kRise * k;
        e.num_points = 20;
        straight.steps.push_back(e);
    }
    estimateGeometry(straight);
    std::vector<Staircase> beside = {spiralPiece(0, 4), straight};
    EXPECT_EQ(dropSpiralRepeats(beside), 0);
    EXPECT_EQ(beside.size(), 2u);
    // a descending flight is never a piece
    Staircase down = spiralPiece(8, 12);
    down.direction = StairDirection::Descending;
    std::vector<Staircase> with_descent = {spiralPiece(0, 4), down};
    EXPECT_EQ(dropSpiralRepeats(with_descent), 0);
}

}  // namespace
}  // namespace stairmap
