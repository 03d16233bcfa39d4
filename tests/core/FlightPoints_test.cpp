// The crop around a flight's edges used by the sparse-cloud corrections.
#include "core/FlightPoints.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace stairmap {
namespace {

LineSegment edge(double x, double y0, double y1, double z) {
    LineSegment l;
    l.start = {x, y0};
    l.end = {x, y1};
    l.z = z;
    return l;
}

TEST(FlightPoints, KeepsPointsInTheGrownBoxAndTheHeightBand) {
    // Edges span x 2..2.5, y -0.5..0.5; grown by 0.3 m: x 1.7..2.8, y -0.8..0.8.
    const std::vector<LineSegment> edges = {edge(2.0, -0.5, 0.5, 0.1), edge(2.5, -0.4, 0.5, 0.3)};
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const PointCloud cloud = {
        {1.75f, 0.0f, 0.2f},   // inside the margin before the first edge
        {2.75f, -0.75f, 0.0f},  // inside, near a corner of the grown box
        {1.65f, 0.0f, 0.2f},   // 5 cm beyond the margin in x
        {2.2f, 0.85f, 0.2f},   // beyond it in y
        {2.2f, 0.0f, -0.15f},  // below the band
        {2.2f, 0.0f, 0.65f},   // above it
        {nan, 0.0f, 0.2f},     // not finite
        {2.2f, 0.0f, nan},
    };
    const PointCloud kept = pointsNearEdges(cloud, edges, 0.3, -0.1, 0.6);
    ASSERT_EQ(kept.size(), 2u);
    EXPECT_FLOAT_EQ(kept[0].x(), 1.75f);
    EXPECT_FLOAT_EQ(kept[1].x(), 2.75f);
}

TEST(FlightPoints, TheBoxHoldsExactlyThePointsKept) {
    // The corrections test flightBox inline instead of copying: both must select alike, also on
    // the borders and for non-finite points.
    const std::vector<LineSegment> edges = {edge(2.0, -0.5, 0.5, 0.1), edge(2.5, -0.4, 0.5, 0.3)};
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const PointCloud cloud = {{1.75f, 0.0f, 0.2f}, {2.8f, 0.8f, 0.6f},  {1.7f, -0.8f, -0.1f},
                              {1.65f, 0.0f, 0.2f}, {2.2f, 0.0f, 0.65f}, {nan, 0.0f, 0.2f},
                              {2.2f, inf, 0.2f},   {2.2f, 0.0f, -inf}};
    const FlightBox box = flightBox(edges, 0.3, -0.1, 0.6);
    PointCloud inside;
    for (const auto& q : cloud)
        if (box.contains(q)) inside.push_back(q);
    const PointCloud kept = pointsNearEdges(cloud, edges, 0.3, -0.1, 0.6);
    ASSERT_EQ(inside.size(), kept.size());
    for (std::size_t i = 0; i < kept.size(); ++i) EXPECT_EQ(inside[i], kept[i]);
    EXPECT_FALSE(flightBox({}, 1.0, -1.0, 1.0).contains(Eigen::Vector3f(0.f, 0.f, 0.f)));
}

TEST(FlightPoints, FloatBoundsPassEveryPointOfEitherBoxAndRejectFarOnes) {
    // The first test of the riser-top corrections' copy loop: a point either box holds must
    // pass it, exactly on a border too (a float rounded inwards would drop it).
    FlightBox a;
    a.lo = {1.1, -0.7};
    a.hi = {2.3, 0.9};
    a.z_lo = -0.31;
    a.z_hi = 0.47;
    FlightBox b;
    b.lo = {0.4, -0.2};
    b.hi = {1.3, 0.3};
    b.z_lo = -0.9;
    b.z_hi = 0.1;
    const FloatBounds f = floatBounds(a, b);
    const auto on = [](double v) { return static_cast<float>(v); };  // may round outwards
    for (const FlightBox& box : {a, b})
        for (const double x : {box.lo.x(), box.hi.x()})
            for (const double y : {box.lo.y(), box.hi.y()})
                for (const double z : {box.z_lo, box.z_hi}) {
                    const Eigen::Vector3f q(on(x), on(y), on(z));
                    EXPECT_TRUE(f.mayContain(q)) << q.transpose();
                }
    EXPECT_FALSE(f.mayContain({2.5f, 0.f, 0.f}));    // beyond a's far x
    EXPECT_FALSE(f.mayContain({0.8f, 0.f, -1.0f}));  // below b
    EXPECT_FALSE(f.mayContain({0.8f, 1.0f, 0.f}));   // beside both
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(f.mayContain({nan, 0.f, 0.f}));
}

TEST(FlightPoints, NoEdgesKeepNothing) {
    const PointCloud cloud = {{0.f, 0.f, 0.f}, {1.f, 1.f, 0.5f}};
    EXPECT_TRUE(pointsNearEdges(cloud, {}, 1.0, -1.0, 1.0).empty());
}

}  // namespace
}  // namespace stairmap
