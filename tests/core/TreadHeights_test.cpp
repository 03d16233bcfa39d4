// Nosing heights from treads: riser-top edges of a sparse view are raised onto the treads' line.
#include "core/TreadHeights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/HandMadeNosing.h"

namespace stairmap {
namespace {

constexpr double kRise = 0.17, kRun = 0.30, kX0 = 3.0;  // flight along +x, nosing k at x0 + k run

/// Edge k of the flight, across y in [-0.6, 0.6], at height z.
LineSegment edge(int k, double z) { return test::nosingAcrossY(kX0 + k * kRun, z, 0.6); }

double nosingZ(int k) { return k * kRise; }

/// A ring crossing tread k at `behind` [m] behind its nosing: points across the tread's width.
void addTreadRing(PointCloud& cloud, int k, double behind) {
    for (double y = -0.55; y <= 0.55; y += 0.05)
        cloud.emplace_back(kX0 + k * kRun + behind, y, nosingZ(k));
}

TEST(TreadHeights, RiserTopEdgesAreRaisedOntoTheTreadsLine) {
    PointCloud cloud;
    std::vector<LineSegment> edges;
    const double low[5] = {0.04, 0.06, 0.02, 0.05, 0.08};  // riser tops read this low
    for (int k = 0; k < 5; ++k) {
        edges.push_back(edge(k, nosingZ(k) - low[k]));
        if (k < 3) addTreadRing(cloud, k, 0.12);  // the upper two treads are above the sensor
    }
    EXPECT_EQ(raiseEdgesToTreads(cloud, kRise, kRun, edges), 5);
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(edges[k].z, nosingZ(k), 1e-4) << "edge " << k;
}

TEST(TreadHeights, EdgesAreNeverLoweredAndTrueEdgesStay) {
    PointCloud cloud;
    std::vector<LineSegment> edges;
    for (int k = 0; k < 4; ++k) {
        edges.push_back(edge(k, nosingZ(k)));
        addTreadRing(cloud, k, 0.15);
    }
    edges[2].z += 0.03;  // read high (noise): the treads do not pull it down
    EXPECT_EQ(raiseEdgesToTreads(cloud, kRise, kRun, edges), 0);
    EXPECT_NEAR(edges[2].z, nosingZ(2) + 0.03, 1e-9);
    EXPECT_NEAR(edges[0].z, nosingZ(0), 1e-9);
}

TEST(TreadHeights, TwoTreadsAreNotEnough) {
    PointCloud cloud;
    std::vector<LineSegment> edges;
    for (int k = 0; k < 4; ++k) {
        edges.push_back(edge(k, nosingZ(k) - 0.05));
        if (k < 2) addTreadRing(cloud, k, 0.12);
    }
    EXPECT_EQ(raiseEdgesToTreads(cloud, kRise, kRun, edges), 0);
    EXPECT_NEAR(edges[3].z, nosingZ(3) - 0.05, 1e-9);
}

TEST(TreadHeights, APostOrABoxTopIsNoTread) {
    // Each tread holds a post (a ring crossing it: flat but narrow) 3 cm above the edge, and the
    // true tread ring: the lowest wide band wins, and the narrow one alone is no tread.
    PointCloud cloud;
    std::vector<LineSegment> edges;
    for (int k = 0; k < 4; ++k) {
        edges.push_back(edge(k, nosingZ(k) - 0.06));
        for (double y = 0.0; y <= 0.06; y += 0.01)  // post: 6 cm wide, one ring's hits
            cloud.emplace_back(kX0 + k * kRun + 0.15, y, nosingZ(k) - 0.03);
    }
    EXPECT_EQ(raiseEdgesToTreads(cloud, kRise, kRun, edges), 0);
    for (int k = 0; k < 4; ++k) addTreadRing(cloud, k, 0.20);
    EXPECT_EQ(raiseEdgesToTreads(cloud, kRise, kRun, edges), 4);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(edges[k].z, nosingZ(k), 1e-4);
}

TEST(TreadHeights, TheBandsMedianHeightWithOrWithoutAStrayPointUnderIt) {
    // Each tread's ring (inside the edge's trimmed ends) has 17 distinct heights 0.05 mm apart,
    // out of height order along the ring: the band's median is the 9th lowest, 0.4 mm above the
    // nosing. A stray point 3 cm under tread 1 is a band of its own (too few points): the next
    // band up is the same ring.
    PointCloud cloud;
    std::vector<LineSegment> edges;
    for (int k = 0; k < 4; ++k) {
        edges.push_back(edge(k, nosingZ(k) - 0.05));
        for (int i = 0; i < 17; ++i)
            cloud.emplace_back(kX0 + k * kRun + 0.12, -0.4 + 0.05 * i,
                               nosingZ(k) + 0.00005 * ((7 * i) % 17));
    }
    cloud.emplace_back(kX0 + kRun + 0.12, 0.0, nosingZ(1) - 0.03);
    EXPECT_EQ(raiseEdgesToTreads(cloud, kRise, kRun, edges), 4);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(edges[k].z, nosingZ(k) + 0.0004, 1e-6) << "edge " << k;
}

TEST(TreadHeights, ARingOffTheOthersLineIsDropped) {
    // Tread 3's band is a ring on the next riser, 5 cm above its nosing: it is left out of the
    // line, and edge 3 is raised to the line of the other treads (its true height).
    PointCloud cloud;
    std::vector<LineSegment> edges;
    for (int k = 0; k < 5; ++k) {
        edges.push_back(edge(k, nosingZ(k) - 0.03));
        if (k != 3) addTreadRing(cloud, k, 0.12);
    }
    for (double y = -0.55; y <= 0.55; y += 0.05)
        cloud.emplace_back(kX0 + 3 * kRun + 0.2, y, nosingZ(3) + 0.05);
    raiseEdgesToTreads(cloud, kRise, kRun, edges);
    EXPECT_NEAR(edges[3].z, nosingZ(3), 1e-4);
}

TEST(TreadHeights, NonFiniteAndEmptyInputChangeNothing) {
    std::vector<LineSegment> edges = {edge(0, -0.02), edge(1, 0.15), edge(2, 0.32)};
    const float nan = std::numeric_limits<float>::quiet_NaN();
    PointCloud cloud(50, Eigen::Vector3f(nan, nan, nan));
    EXPECT_EQ(raiseEdgesToTreads(cloud, kRise, kRun, edges), 0);
    EXPECT_EQ(raiseEdgesToTreads({}, kRise, kRun, edges), 0);
    EXPECT_EQ(raiseEdgesToTreads(cloud, std::nan(""), kRun, edges), 0);
    std::vector<LineSegment> none;
    EXPECT_EQ(raiseEdgesToTreads(cloud, kRise, kRun, none), 0);
    EXPECT_NEAR(edges[0].z, -0.02, 1e-12);
}

}  // namespace
}  // namespace stairmap
