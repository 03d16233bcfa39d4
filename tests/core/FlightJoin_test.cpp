// Two chains of one flight are joined (consistent) or the far one dropped (corrupted); separate
// flights stay separate.
#include "core/FlightJoin.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/StaircaseGeometry.h"

namespace stairmap {
namespace {

constexpr double kRise = 0.17, kRun = 0.28, kWidth = 1.2;

/// Ascending flight along +x: steps first..last (step k: nosing at x0 + k run, z0 + k rise),
/// lateral centre y_c, optional extra height on every edge.
Staircase flight(int first, int last, double y_c = 0.0, double x0 = 1.5, double dz = 0.0) {
    Staircase s;
    s.direction = StairDirection::Ascending;
    for (int k = first; k <= last; ++k) {
        StairEdge e;
        const double x = x0 + k * kRun, z = -0.33 + k * kRise + dz;
        e.start = {x, y_c + kWidth / 2, z};
        e.end = {x, y_c - kWidth / 2, z};
        s.steps.push_back(e);
    }
    estimateGeometry(s);
    return s;
}

TEST(FlightJoin, AConsistentContinuationIsAppended) {
    std::vector<Staircase> found = {flight(4, 6), flight(0, 3)};
    EXPECT_EQ(joinContinuedFlights(found, FlightJoinParams{}), 1);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].steps.size(), 7u);
    EXPECT_NEAR(found[0].step_height, kRise, 1e-9);
    EXPECT_NEAR(found[0].step_depth, kRun, 1e-9);
    EXPECT_NEAR(found[0].location.x(), 1.5, 1e-9);  // still the first step's edge
}

TEST(FlightJoin, ACorruptedContinuationIsDroppedAndTheAnchoredChainKept) {
    std::vector<Staircase> found = {flight(0, 3), flight(4, 8, 0.0, 1.5, 0.09)};  // 9 cm too high
    EXPECT_EQ(joinContinuedFlights(found, FlightJoinParams{}), 1);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].steps.size(), 4u);
    EXPECT_NEAR(found[0].steps.front().centre().z(), -0.33, 1e-9);
}

TEST(FlightJoin, AContinuationWhoseFacingEdgeIsAPieceIsStillRecognised) {
    // the far chain's first edge is a 0.4 m piece mostly beside the near chain's last edge (a
    // broken nosing); the far chain is 9 cm too high, so it is dropped, not appended
    Staircase far = flight(4, 8, 0.0, 1.5, 0.09);
    far.steps.front().start.y() = -0.5;
    far.steps.front().end.y() = -0.9;
    estimateGeometry(far);
    std::vector<Staircase> found = {flight(0, 3), far};
    EXPECT_EQ(joinContinuedFlights(found, FlightJoinParams{}), 1);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].steps.size(), 4u);
}

TEST(FlightJoin, ChainsMeetingAtALevelAreOneFlight) {
    // A nosing broken by debris ends the first chain at step 3; the search starts another on a
    // second line of that nosing (2 cm lower, beside the first), up to step 10.
    Staircase far = flight(3, 10);
    far.steps.front().start += Eigen::Vector3d(0.0, -0.7, -0.02);
    far.steps.front().end += Eigen::Vector3d(0.0, -0.7, -0.02);
    estimateGeometry(far);
    std::vector<Staircase> found = {flight(0, 3), far};
    EXPECT_EQ(joinContinuedFlights(found, FlightJoinParams{}), 1);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].steps.size(), 11u);
    EXPECT_NEAR(found[0].steps.front().centre().z(), -0.33, 1e-9);
    EXPECT_NEAR(found[0].step_height, kRise, 0.005);
    EXPECT_NEAR(found[0].step_depth, kRun, 0.005);
}

TEST(FlightJoin, OfChainsMeetingAtALevelOnDifferentRisesTheLongerIsKept) {
    // The near chain's rise is 3.5 cm too large (lines on debris below its top edge): the joined
    // edges do not lie on one rise, and the longer far chain is the better view.
    Staircase near = flight(0, 3);
    for (std::size_t k = 0; k < near.steps.size(); ++k) {
        const double dz = -0.035 * static_cast<double>(3 - k);
        near.steps[k].start.z() += dz;
        near.steps[k].end.z() += dz;
    }
    estimateGeometry(near);
    std::vector<Staircase> found = {near, flight(3, 10)};
    EXPECT_EQ(joinContinuedFlights(found, FlightJoinParams{}), 1);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].steps.size(), 8u);
    EXPECT_NEAR(found[0].steps.front().centre().z(), -0.33 + 3 * kRise, 1e-9);
}

/// Joins flight(0, near_last) and flight(far_first, last): one flight of steps 0..last, the steps
/// between put back unseen on the flight's nosing line.
void expectJoinedWithUnseenPutBack(int near_last, int far_first, int last) {
    std::vector<Staircase> found = {flight(0, near_last), flight(far_first, last)};
    EXPECT_EQ(joinContinuedFlights(found, FlightJoinParams{}), 1);
    ASSERT_EQ(found.size(), 1u);
    ASSERT_EQ(found[0].steps.size(), static_cast<std::size_t>(last + 1));
    for (int k = near_last + 1; k < far_first; ++k) {
        EXPECT_EQ(found[0].steps[k].num_points, 0) << "step " << k;
        EXPECT_NEAR(found[0].steps[k].centre().x(), 1.5 + k * kRun, 1e-9) << "step " << k;
        EXPECT_NEAR(found[0].steps[k].centre().z(), -0.33 + k * kRise, 1e-9) << "step " << k;
    }
    EXPECT_NEAR(found[0].step_height, kRise, 1e-9);
    EXPECT_NEAR(found[0].step_depth, kRun, 1e-9);
}

TEST(FlightJoin, AContinuationAfterUnseenStepsIsAppendedWithThemPutBack) {
    // steps 3 and 4 unseen (a far LiDAR's rings skipped them): the far chain lies on the near
    // one's nosing line at its own index
    expectJoinedWithUnseenPutBack(2, 5, 9);
}

TEST(FlightJoin, FourUnseenStepsArePutBack) {
    // a pitched OS0-128's rings left steps 4-7 of a 15-step flight unseen (dev5 r0626)
    expectJoinedWithUnseenPutBack(3, 8, 12);
}

TEST(FlightJoin, AContinuationOnTheCommonLineIsAppendedWhenTheNearRiseReadsOff) {
    // the near chain's rise reads 6 % high (0.180 m on 0.170 m): five steps on, the far chain
    // lies 8 cm below its line, but both lie on the line fitted over the two (dev6 r0478)
    Staircase near = flight(0, 4);
    for (std::size_t k = 0; k < near.steps.size(); ++k) {
        near.steps[k].start.z() += 0.01 * k;
        near.steps[k].end.z() += 0.01 * k;
    }
    estimateGeometry(near);
    std::vector<Staircase> found = {near, flight(5, 9)};
    EXPECT_EQ(joinContinuedFlights(found, FlightJoinParams{}), 1);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].steps.size(), 10u);
    EXPECT_NEAR(found[0].step_height, kRise, 0.005);
}

TEST(FlightJoin, AChainOffTheCommonLineIsNotAppended) {
    // the far chain 0.7 rise above the near one's line (5 cm off the line fitted over both):
    // another surface, not these steps
    std::vector<Staircase> found = {flight(0, 4), flight(5, 9, 0.0, 1.5, 0.7 * kRise)};
    joinContinuedFlights(found, FlightJoinParams{});
    for (const Staircase& s : found) EXPECT_LE(s.steps.size(), 5u);
}

TEST(FlightJoin, MoreUnseenStepsThanAllowedKeepTheChainsApart) {
    std::vector<Staircase> found = {flight(0, 2), flight(8, 11)};  // five unseen, four allowed
    EXPECT_EQ(joinContinuedFlights(found, FlightJoinParams{}), 0);
    EXPECT_EQ(found.size(), 2u);
    FlightJoinParams two;
    two.max_unseen_steps = 2;
    found = {flight(0, 2), flight(6, 9)};  // three unseen, two allowed
    EXPECT_EQ(joinContinuedFlights(found, two), 0);
    EXPECT_EQ(found.size(), 2u);
}

/// flight(first, last, y_c) with every edge turned by `deg` about its centre: a short chain
/// whose heading reads off.
Staircase turnedFlight(int first, int last, double y_c, double deg) {
    Staircase s = flight(first, last, y_c);
    const Eigen::Matrix3d r =
        Eigen::AngleAxisd(deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (StairEdge& e : s.steps) {
        const Eigen::Vector3d c = e.centre();
        e.start = c + r * (e.start - c);
        e.end = c + r * (e.end - c);
    }
    estimateGeometry(s);
    return s;
}

TEST(FlightJoin, AShortPieceBesideTheFlightAfterAnUnseenStepIsAppended) {
    // a wide flight seen on its right up to step 5 and on its left at steps 7-9, whose three
    // short edges read 20 deg turned; the two pieces' lateral extents 5 cm apart
    std::vector<Staircase> found = {flight(0, 5), turnedFlight(7, 9, kWidth + 0.05, 20.0)};
    EXPECT_EQ(joinContinuedFlights(found, FlightJoinParams{}), 1);
    ASSERT_EQ(found.size(), 1u);
    ASSERT_EQ(found[0].steps.size(), 10u);
    EXPECT_EQ(found[0].steps[6].num_points, 0);
    EXPECT_NEAR(found[0].step_height, kRise, 1e-9);
}

TEST(FlightJoin, PiecesFarApartSideBySideOrTurnedMoreStaySeparate) {
    std::vector<Staircase> apart = {flight(0, 5), turnedFlight(7, 9, kWidth + 0.3, 20.0)};
    EXPECT_EQ(joinContinuedFlights(apart, FlightJoinParams{}), 0);
    std::vector<Staircase> turned = {flight(0, 5), turnedFlight(7, 9, kWidth + 0.05, 35.0)};
    EXPECT_EQ(joinContinuedFlights(turned, FlightJoinParams{}), 0);
    // four edges: its heading is trusted to the adjacent chains' 15 deg
    std::vector<Staircase> longer = {flight(0, 5), turnedFlight(7, 10, kWidth + 0.05, 20.0)};
    EXPECT_EQ(joinContinuedFlights(longer, FlightJoinParams{}), 0);
}

TEST(FlightJoin, SeparateFlightsStaySeparate) {
    // side by side (no lateral overlap), beyond a 1.5 m landing, and one descending
    std::vector<Staircase> found = {flight(0, 4), flight(0, 4, 2.0), flight(5, 8, 0.0, 3.0)};
    Staircase down = flight(0, 4, 0.0, -1.5);
    down.direction = StairDirection::Descending;
    found.push_back(down);
    EXPECT_EQ(joinContinuedFlights(found, FlightJoinParams{}), 0);
    EXPECT_EQ(found.size(), 4u);
}

}  // namespace
}  // namespace stairmap
