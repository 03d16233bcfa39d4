// Two chains of one flight are joined (consistent) or the far one dropped (corrupted); separate
// flights stay separate.
#include "core/FlightJoin.h"

#include <gtest/gtest.h>

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
