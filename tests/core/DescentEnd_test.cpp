// The lowest edge of a descending chain: an elevation map's crop line on the floor below, several
// times longer than the flight's steps and nothing beyond it, is dropped; a flight's own edges, and
// a long lowest edge with the floor seen beyond it, are kept.
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
    EXPECT_TRUE(dropCropLineEnd(PointCloud{}, edges));
    ASSERT_EQ(edges.size(), 5u);
    EXPECT_NEAR(edges.back().length(), 0.83, 1e-9);
}

TEST(DescentEnd, ALongLowestNosingWithTheFloorBeyondIsKept) {
    // the lowest nosing seen whole under nosings seen in pieces of at most 0.7 m (dev6 r0643): the
    // floor below is seen beyond it (x >= 2.3 m), so it is no crop line; cut away, it would be
    std::vector<LineSegment> edges = flight({0.6, 0.7, 0.7, 0.65, 2.3});
    PointCloud floor_beyond;
    for (double x = 2.3; x < 3.5; x += 0.05)
        for (double y = -1.5; y < 1.5; y += 0.05)
            floor_beyond.emplace_back(static_cast<float>(x), static_cast<float>(y), -1.2f);
    EXPECT_FALSE(dropCropLineEnd(floor_beyond, edges));
    EXPECT_EQ(edges.size(), 5u);
    PointCloud cut;
    for (const Eigen::Vector3f& q : floor_beyond)
        if (q.x() > 2.75f) cut.push_back(q);  // nothing within 0.5 m beyond the edge at x = 2.2
    EXPECT_TRUE(dropCropLineEnd(cut, edges));
    EXPECT_EQ(edges.size(), 4u);
}

TEST(DescentEnd, AFlightsOwnEdgesAreKept) {
    // the lowest edge the longest of a flight whose upper edges were seen in pieces: under 3x
    std::vector<LineSegment> edges = flight({0.5, 0.6, 0.6, 1.7});
    EXPECT_FALSE(dropCropLineEnd(PointCloud{}, edges));
    EXPECT_EQ(edges.size(), 4u);
    std::vector<LineSegment> equal = flight({1.2, 1.2, 1.2});
    EXPECT_FALSE(dropCropLineEnd(PointCloud{}, equal));
    EXPECT_EQ(equal.size(), 3u);
}

TEST(DescentEnd, OnlyTheLowestEdgeIsAsked) {
    // a long first edge (the floor's own, a landing's) is no crop line of the floor below
    std::vector<LineSegment> edges = flight({7.0, 1.0, 1.0, 1.0});
    EXPECT_FALSE(dropCropLineEnd(PointCloud{}, edges));
    EXPECT_EQ(edges.size(), 4u);
    std::vector<LineSegment> one = flight({5.0});
    EXPECT_FALSE(dropCropLineEnd(PointCloud{}, one));
    EXPECT_EQ(one.size(), 1u);
}

TEST(DescentEnd, TheRatioIsAParameter) {
    std::vector<LineSegment> edges = flight({1.0, 1.0, 2.5});
    DescentEndParams p;
    EXPECT_FALSE(dropCropLineEnd(PointCloud{}, edges, p));
    p.max_length_ratio = 2.0;
    EXPECT_TRUE(dropCropLineEnd(PointCloud{}, edges, p));
    EXPECT_EQ(edges.size(), 2u);
}

}  // namespace
}  // namespace stairmap
