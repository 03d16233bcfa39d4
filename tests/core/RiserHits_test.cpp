// Riser hits of a sparse LiDAR: lines under a nosing are dropped, low edges of a flight are raised.
#include "core/RiserHits.h"

#include <gtest/gtest.h>

namespace stairmap {
namespace {

/// An edge across the flight (along y) at x, height z, from y0 to y1.
LineSegment edge(double x, double z, double y0 = -0.6, double y1 = 0.6) {
    LineSegment l;
    l.start = {x, y0};
    l.end = {x, y1};
    l.z = z;
    l.rho = x;  // normal along +x
    l.theta = 0.0;
    return l;
}

TEST(RiserHits, ALineUnderANosingIsDroppedOthersStay) {
    std::vector<LineSegment> lines = {
        edge(3.72, 0.16),              // lower nosing, one run before
        edge(4.01, 0.27),              // riser hit 6 cm under the next nosing, 1 cm off across
        edge(4.00, 0.33),              // the nosing
        edge(4.00, -0.05, 0.4, 0.6),   // more than a rise under both: not a riser hit
        edge(4.20, 0.43, -0.1, 0.05),  // debris on the tread above: covers too little of the nosing
    };
    dropRiserHits(lines, RiserHitParams{});
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_DOUBLE_EQ(lines[0].z, 0.16);
    EXPECT_DOUBLE_EQ(lines[1].z, 0.33);
    EXPECT_DOUBLE_EQ(lines[2].z, -0.05);
    EXPECT_DOUBLE_EQ(lines[3].z, 0.43);
}

TEST(RiserHits, ALineBesideANosingIsNoRiserHit) {
    std::vector<LineSegment> lines = {edge(4.10, 0.27), edge(4.00, 0.33)};  // 10 cm apart across
    dropRiserHits(lines, RiserHitParams{});
    EXPECT_EQ(lines.size(), 2u);
}

std::vector<LineSegment> flight(int n, double z0, double rise) {
    std::vector<LineSegment> edges;
    for (int k = 0; k < n; ++k) edges.push_back(edge(1.5 + 0.28 * k, z0 + rise * k));
    return edges;
}

TEST(RiserHits, LowEdgesAreRaisedOntoTheFlightsNosingLine) {
    std::vector<LineSegment> edges = flight(8, -0.18, 0.17);
    edges[3].z -= 0.05;
    edges[6].z -= 0.07;
    EXPECT_EQ(raiseLowEdges(edges, 0.02), 2);
    for (int k = 0; k < 8; ++k) EXPECT_NEAR(edges[k].z, -0.18 + 0.17 * k, 1e-9) << k;
}

TEST(RiserHits, AConsistentFlightIsLeftAlone) {
    std::vector<LineSegment> edges = flight(6, 0.2, -0.18);  // descending: heights fall
    edges[2].z += 0.008;                                     // noise within the tolerance
    const auto before = edges;
    EXPECT_EQ(raiseLowEdges(edges, 0.02), 0);
    for (std::size_t k = 0; k < edges.size(); ++k) EXPECT_EQ(edges[k].z, before[k].z);
}

TEST(RiserHits, NothingIsRaisedWhenMostEdgesWouldBeSetAside) {
    std::vector<LineSegment> edges = flight(3, 0.0, 0.17);
    edges[1].z -= 0.06;  // two of three would have to carry the fit
    const auto before = edges;
    EXPECT_EQ(raiseLowEdges(edges, 0.02), 0);
    EXPECT_EQ(edges[1].z, before[1].z);
}

}  // namespace
}  // namespace stairmap
