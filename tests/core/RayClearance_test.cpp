// Nosing heights bounded by the rays that cleared them: a sparse LiDAR's riser-top edges are moved
// onto the line inside [riser hit, ray clearance] of every step.
#include "core/RayClearance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/FlightPoints.h"
#include "support/RingScannedFlight.h"

namespace stairmap {
namespace {

using Flight = test::RingScannedFlight;
using test::riserTopEdge;
using test::scanFlight;

TEST(RayClearance, RiserTopEdgesOfAFarFlightMoveOntoTheNosings) {
    Flight f;
    const PointCloud cloud = scanFlight(f);
    std::vector<LineSegment> edges;
    double worst_before = 0;
    for (int k = 0; k < f.steps - 1; ++k) {
        edges.push_back(riserTopEdge(cloud, f, k));
        ASSERT_TRUE(std::isfinite(edges.back().z)) << "riser " << k << " not hit";
        worst_before = std::max(worst_before, f.nosingZ(k) - edges.back().z);
    }
    ASSERT_GT(worst_before, 0.06);  // the case this fixes: riser tops well under their nosings
    const double measured_rise = (edges.back().z - edges.front().z) / (edges.size() - 1);
    EXPECT_GT(fitEdgesToRayClearance(cloud, measured_rise, f.run, edges), 0);
    for (int k = 0; k < f.steps - 1; ++k)
        EXPECT_NEAR(edges[k].z, f.nosingZ(k), 0.03) << "edge " << k;
}

TEST(RayClearance, ClearanceIsWhereTheRayToAPointBehindCrossesTheNosing) {
    std::vector<LineSegment> edges(2);
    for (int k = 0; k < 2; ++k) {
        edges[k].start = {4.0 + 0.3 * k, -0.5};
        edges[k].end = {4.0 + 0.3 * k, 0.5};
        edges[k].z = 0.1 + 0.17 * k;
    }
    // Three points 0.2 m behind the first edge at 0.5 m height: their rays from the origin cross
    // x = 4 at 0.5 * 4 / 4.2; a point beside the flight and one under the tread do not count.
    PointCloud cloud = {{4.2f, 0.0f, 0.5f}, {4.2f, 0.1f, 0.5f}, {4.2f, -0.1f, 0.5f},
                        {4.2f, 2.0f, 0.3f}, {4.2f, 0.0f, 0.0f}};
    EXPECT_NEAR(nosingClearance(cloud, edges, 0, 0.3), 0.5 * 4.0 / 4.2, 1e-6);
    // Only the third lowest ray counts: a higher one or a point without height changes nothing.
    PointCloud more = cloud;
    more.emplace_back(4.2f, 0.05f, 0.9f);
    more.emplace_back(4.2f, 0.05f, std::nanf(""));
    EXPECT_EQ(nosingClearance(more, edges, 0, 0.3), nosingClearance(cloud, edges, 0, 0.3));
    more.emplace_back(4.2f, 0.05f, 0.45f);  // a lower one does
    EXPECT_NEAR(nosingClearance(more, edges, 0, 0.3), 0.5 * 4.0 / 4.2, 1e-6);
    more.emplace_back(4.2f, -0.05f, 0.4f);
    more.emplace_back(4.2f, -0.05f, 0.42f);
    EXPECT_NEAR(nosingClearance(more, edges, 0, 0.3), 0.45 * 4.0 / 4.2, 1e-6);
    cloud.resize(2);  // fewer rays than clearance_rank: no bound
    EXPECT_TRUE(std::isinf(nosingClearance(cloud, edges, 0, 0.3)));
}

TEST(RayClearance, ARisersOwnTopHitsBehindItsLineBoundNothing) {
    std::vector<LineSegment> edges(2);
    for (int k = 0; k < 2; ++k) {
        edges[k].start = {5.0 + 0.3 * k, -0.5};
        edges[k].end = {5.0 + 0.3 * k, 0.5};
        edges[k].z = -0.07 + 0.19 * k;
    }
    // The riser's highest ring (the edge's own height), its range noise (HDL-32: 2 cm) putting
    // some hits 5 cm behind the edge's line: no ray crossed above the nosing there (dev r0258: a
    // bound 6 mm over the edge, 13 cm under the nosing, made the flight's line infeasible).
    PointCloud cloud;
    for (int i = 0; i < 5; ++i) cloud.emplace_back(5.05f, -0.2f + 0.1f * i, -0.07f);
    EXPECT_TRUE(std::isinf(nosingClearance(cloud, edges, 0, 0.3)));
    // The next riser's hits, a run behind, still bound it.
    for (int i = 0; i < 5; ++i) cloud.emplace_back(5.3f, -0.2f + 0.1f * i, 0.05f);
    EXPECT_NEAR(nosingClearance(cloud, edges, 0, 0.3), 0.05 * 5.0 / 5.3, 1e-6);
}

TEST(RayClearance, AllEdgesInOnePassEqualEachEdgeAlone) {
    Flight f;
    const PointCloud cloud = scanFlight(f);
    std::vector<LineSegment> edges;
    for (int k = 0; k < f.steps - 1; ++k) edges.push_back(riserTopEdge(cloud, f, k));
    // A box that cuts the flight's points (above the third nosing) and one that holds them all;
    // a high rank makes the bound depend on many rays, not only the lowest.
    const double z_lo = edges.front().z - 0.01;
    RayClearanceParams p;
    for (const int rank : {3, 30})
        for (const double z_hi : {f.nosingZ(2), 10.0}) {
            p.clearance_rank = rank;
            const FlightBox box = flightBox(edges, 0.6, z_lo, z_hi);
            const PointCloud inside = pointsNearEdges(cloud, edges, 0.6, z_lo, z_hi);
            const std::vector<double> all = nosingClearances(cloud, box, edges, f.run, p);
            ASSERT_EQ(all.size(), edges.size());
            int bounded = 0;
            for (std::size_t k = 0; k < edges.size(); ++k) {
                EXPECT_EQ(all[k], nosingClearance(inside, edges, k, f.run, p))
                    << "edge " << k << " rank " << rank << " z_hi " << z_hi;
                bounded += std::isfinite(all[k]);
            }
            EXPECT_GE(bounded, 2) << "rank " << rank << " z_hi " << z_hi;  // a test of something
        }
    EXPECT_TRUE(std::isinf(nosingClearances(cloud, flightBox(edges, 0.6, z_lo, 10.0),
                                            {edges.front()}, f.run)[0]));
}

TEST(RayClearance, NothingMovesWithoutBoundsOrWhenTheyPinNothing) {
    Flight f;
    std::vector<LineSegment> edges;
    const PointCloud cloud = scanFlight(f);
    for (int k = 0; k < f.steps - 1; ++k) edges.push_back(riserTopEdge(cloud, f, k));
    const std::vector<LineSegment> before = edges;
    const double rise = (edges.back().z - edges.front().z) / (edges.size() - 1);
    EXPECT_EQ(fitEdgesToRayClearance(PointCloud{}, rise, f.run, edges), 0);
    RayClearanceParams narrow;
    narrow.max_feasible_width_m = 0.001;  // the bounds span more than this: left alone
    EXPECT_EQ(fitEdgesToRayClearance(cloud, rise, f.run, edges, narrow), 0);
    PointCloud hostile = cloud;
    hostile.emplace_back(std::nanf(""), 0.0f, 0.0f);
    hostile.emplace_back(std::numeric_limits<float>::infinity(), 0.0f, 0.5f);
    std::vector<LineSegment> with_hostile = edges;
    fitEdgesToRayClearance(hostile, rise, f.run, with_hostile);
    std::vector<LineSegment> clean = edges;
    fitEdgesToRayClearance(cloud, rise, f.run, clean);
    for (std::size_t k = 0; k < edges.size(); ++k) {
        EXPECT_EQ(edges[k].z, before[k].z);
        EXPECT_DOUBLE_EQ(with_hostile[k].z, clean[k].z);  // non-finite points are ignored
    }
}

}  // namespace
}  // namespace stairmap
