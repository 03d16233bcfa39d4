// Algorithm 2 on the detector's own chains: split halves are merged, a second weaker view of a
// flight is absorbed, and different flights (beside, beyond a landing, other direction) stay apart.
#include "core/OverlappingFlights.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/StaircaseGeometry.h"

namespace stairmap {
namespace {

constexpr double kRise = 0.17, kRun = 0.28, kWidth = 1.4, kZ0 = -0.33;

/// Edge of step k of a flight along +x (nosing at x = 1.5 + k run), from lateral y_lo to y_hi,
/// turned by `skew_deg` about its centre and moved `dx` along the flight.
StairEdge edge(int k, double y_lo, double y_hi, double skew_deg = 0.0, double dx = 0.0) {
    const double x = 1.5 + k * kRun + dx, z = kZ0 + k * kRise, yc = 0.5 * (y_lo + y_hi);
    const double half = 0.5 * (y_hi - y_lo), a = skew_deg * M_PI / 180.0;
    StairEdge e;
    e.start = {x - half * std::sin(a), yc + half * std::cos(a), z};
    e.end = {x + half * std::sin(a), yc - half * std::cos(a), z};
    return e;
}

Staircase stairs(std::vector<StairEdge> edges, StairDirection dir = StairDirection::Ascending) {
    Staircase s;
    s.direction = dir;
    s.steps = std::move(edges);
    estimateGeometry(s);
    return s;
}

Staircase whole(int first, int last, double y_c = 0.0) {
    std::vector<StairEdge> e;
    for (int k = first; k <= last; ++k) e.push_back(edge(k, y_c - kWidth / 2, y_c + kWidth / 2));
    return stairs(e);
}

TEST(OverlappingFlights, ASecondViewOnTheTreadsIsAbsorbedAndTheLongerChainKept) {
    // pieces of steps 1-4, skewed 25 deg, 8 cm behind their nosings (broken lines of one flight)
    std::vector<StairEdge> pieces;
    for (int k = 1; k <= 4; ++k) pieces.push_back(edge(k, 0.1, 0.45, 25.0, 0.08));
    std::vector<Staircase> found = {stairs(pieces), whole(0, 7)};
    EXPECT_EQ(edgesOnTreads(found[1], found[0], {}), 4);
    EXPECT_EQ(mergeOverlappingFlights(found), 1);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].steps.size(), 8u);
    EXPECT_NEAR(found[0].step_height, kRise, 1e-9);
    EXPECT_NEAR(found[0].step_depth, kRun, 1e-9);
    EXPECT_NEAR(found[0].step_width, kWidth, 1e-9);  // skewed pieces are not fused into edges
}

TEST(OverlappingFlights, CollinearPiecesOfASecondViewExtendTheEdges) {
    // the first view sees the left 0.8 m of each nosing, the second 0.5 m on the right of a gap
    std::vector<StairEdge> left, right;
    for (int k = 0; k <= 5; ++k) left.push_back(edge(k, -0.1, 0.7));
    for (int k = 1; k <= 4; ++k) right.push_back(edge(k, -0.7, -0.2));
    std::vector<Staircase> found = {stairs(right), stairs(left)};
    EXPECT_EQ(mergeOverlappingFlights(found), 1);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].steps.size(), 6u);
    EXPECT_NEAR(found[0].steps[2].length(), 1.4, 0.01);  // the union: -0.7 .. 0.7
}

TEST(OverlappingFlights, SplitHalvesFarApartAreMerged) {
    // debris in the middle: two halves 0.8 m apart, every level collinear (Definition 2)
    std::vector<StairEdge> a, b;
    for (int k = 0; k <= 5; ++k) a.push_back(edge(k, 0.4, 1.2));
    for (int k = 0; k <= 3; ++k) b.push_back(edge(k, -1.2, -0.4));
    std::vector<Staircase> found = {stairs(a), stairs(b)};
    EXPECT_EQ(mergeOverlappingFlights(found), 1);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].steps.size(), 6u);
    EXPECT_NEAR(found[0].steps[1].length(), 2.4, 0.01);
}

TEST(OverlappingFlights, SparseHalvesSideBySideAreOneFlight) {
    // A far view: each half's short edges scatter by +-7 deg (14 deg between the halves at a
    // level, beyond Definition 2's 10 deg) and by 1.5 cm along the flight; 0.3 m between them.
    std::vector<StairEdge> left, right;
    for (int k = 0; k <= 4; ++k) {
        const double skew = (k % 2 ? 7.0 : -7.0), dx = (k % 2 ? 0.015 : -0.015);
        left.push_back(edge(k, 0.15, 0.7, skew, dx));
        right.push_back(edge(k, -0.7, -0.15, -skew, -dx));
    }
    right.pop_back();  // the right half is seen to step 3 only
    std::vector<Staircase> found = {stairs(right), stairs(left)};
    EXPECT_TRUE(sideBySideHalves(found[0], found[1], {}));
    EXPECT_EQ(mergeOverlappingFlights(found), 1);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].steps.size(), 5u);
    EXPECT_NEAR(found[0].steps[1].length(), 1.4, 0.1);  // over both halves
    // Half a run apart along the flight (another flight beside it, offset): apart.
    std::vector<StairEdge> shifted;
    for (int k = 0; k <= 4; ++k) shifted.push_back(edge(k, -0.7, -0.15, 0.0, 0.5 * kRun));
    EXPECT_FALSE(sideBySideHalves(stairs(left), stairs(shifted), {}));
    // Beside it beyond the lateral gap limit (1 m between them): apart.
    std::vector<StairEdge> far_side;
    for (int k = 0; k <= 4; ++k) far_side.push_back(edge(k, -1.55, -0.85));
    EXPECT_FALSE(sideBySideHalves(stairs(left), stairs(far_side), {}));
}

TEST(OverlappingFlights, DifferentFlightsStayApart) {
    // beside it (0.5 m apart, 0.1 m higher: not collinear), beyond a landing, and descending
    std::vector<Staircase> found = {whole(0, 5), whole(0, 5, 1.9), whole(9, 13)};
    for (StairEdge& e : found[1].steps) {
        e.start.z() += 0.06;
        e.end.z() += 0.06;
    }
    estimateGeometry(found[1]);
    Staircase down = whole(0, 5);
    down.direction = StairDirection::Descending;
    found.push_back(down);
    EXPECT_EQ(mergeOverlappingFlights(found), 0);
    EXPECT_EQ(found.size(), 4u);
}

TEST(OverlappingFlights, EmptyInputIsFine) {
    std::vector<Staircase> found;
    EXPECT_EQ(mergeOverlappingFlights(found), 0);
    EXPECT_EQ(edgesOnTreads(Staircase{}, whole(0, 3), {}), 0);
}

}  // namespace
}  // namespace stairmap
