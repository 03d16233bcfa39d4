// The lowest edge of a descending chain: an elevation map's crop line on the floor below, several
// times longer than the flight's steps, is dropped; a flight's own edges are kept.
#include "core/DescentEnd.h"

#include <gtest/gtest.h>

namespace stairmap {
namespace {

/// Edge across y in [-length / 2, length / 2] at x, height z (a flight down +x).
LineSegment edge(double x, double z, double length) {
    LineSegment l;
    l.start = {x, 0.5 * length};
    l.end = {x, -0.5 * length};
    l.z = z;
    l.num_points = 30;
    return l;
}

std::vector<LineSegment> flight(const std::vector<double>& lengths) {
    std::vector<LineSegment> edges;
    for (std::size_t k = 0; k < lengths.size(); ++k)
        edges.push_back(edge(1.0 + 0.3 * k, -0.2 - 0.18 * k, lengths[k]));
    return edges;
}

TEST(DescentEnd, ACropLineBeyondTheLowestNosingIsDropped) {
    // pieces of 0.7-1.8 m, then the floor below's crop line across the whole map (dev5 r0695)
    std::vector<LineSegment> edges = flight({1.8, 0.7, 0.87, 0.87, 0.83, 7.95});
    EXPECT_TRUE(dropCropLineEnd(edges));
    ASSERT_EQ(edges.size(), 5u);
    EXPECT_NEAR(edges.back().length(), 0.83, 1e-9);
}

TEST(DescentEnd, AFlightsOwnEdgesAreKept) {
    // the lowest edge the longest of a flight whose upper edges were seen in pieces: under 3x
    std::vector<LineSegment> edges = flight({0.5, 0.6, 0.6, 1.7});
    EXPECT_FALSE(dropCropLineEnd(edges));
    EXPECT_EQ(edges.size(), 4u);
    std::vector<LineSegment> equal = flight({1.2, 1.2, 1.2});
    EXPECT_FALSE(dropCropLineEnd(equal));
    EXPECT_EQ(equal.size(), 3u);
}

TEST(DescentEnd, OnlyTheLowestEdgeIsAsked) {
    // a long first edge (the floor's own, a landing's) is no crop line of the floor below
    std::vector<LineSegment> edges = flight({7.0, 1.0, 1.0, 1.0});
    EXPECT_FALSE(dropCropLineEnd(edges));
    EXPECT_EQ(edges.size(), 4u);
    std::vector<LineSegment> one = flight({5.0});
    EXPECT_FALSE(dropCropLineEnd(one));
    EXPECT_EQ(one.size(), 1u);
}

TEST(DescentEnd, TheRatioIsAParameter) {
    std::vector<LineSegment> edges = flight({1.0, 1.0, 2.5});
    DescentEndParams p;
    EXPECT_FALSE(dropCropLineEnd(edges, p));
    p.max_length_ratio = 2.0;
    EXPECT_TRUE(dropCropLineEnd(edges, p));
    EXPECT_EQ(edges.size(), 2u);
}

}  // namespace
}  // namespace stairmap
