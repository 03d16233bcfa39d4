// Definition 2 and merge(l_i, l_j) of the paper's Algorithm 2 on exact edges with known answers.
#include <gtest/gtest.h>

#include <cmath>

#include "core/StairEdgeFusion.h"

namespace stairmap {
namespace {

/// An edge along y at x, from y_left (start, left when facing +x) to y_right, at height z.
StairEdge edgeAlongY(double x, double y_left, double y_right, double z = 0.2) {
    StairEdge e;
    e.start = {x, y_left, z};
    e.end = {x, y_right, z};
    e.cov_rho_theta = Eigen::Vector2d(1e-4, 1e-4).asDiagonal();
    e.num_points = 20;
    return e;
}

TEST(DefinitionTwo, PaperThresholdsOnHeightDistanceAndAngle) {
    const StairEdge a = edgeAlongY(2.0, 0.6, -0.6);
    EXPECT_TRUE(isSameStairEdge(a, edgeAlongY(2.04, 0.6, -0.6, 0.24)));
    EXPECT_FALSE(isSameStairEdge(a, edgeAlongY(2.0, 0.6, -0.6, 0.26))) << "z differs by 6 cm";
    EXPECT_FALSE(isSameStairEdge(a, edgeAlongY(2.06, 0.6, -0.6))) << "lines 6 cm apart";
    // b turned about its centre: by 12 deg it is another stair, by 8 deg the same.
    for (const double deg : {12.0, 8.0}) {
        StairEdge turned = a;
        const double t = std::tan(deg * M_PI / 180.0) * 0.6;
        turned.start.x() -= t;
        turned.end.x() += t;
        EXPECT_EQ(isSameStairEdge(a, turned), deg < 10.0) << deg << " deg apart";
    }
}

TEST(DefinitionTwo, DistanceIsBetweenTheLinesNotTheCentres) {
    // A partial view of the left end: centres 45 cm apart, lines 1 cm apart.
    EXPECT_TRUE(isSameStairEdge(edgeAlongY(2.0, 0.6, -0.6), edgeAlongY(2.01, 0.6, 0.3)));
}

TEST(DefinitionTwo, OverlapGateSplitsOrKeepsCollinearEdges) {
    const StairEdge left = edgeAlongY(2.0, 0.6, 0.05), right = edgeAlongY(2.0, -0.15, -0.6);
    // Default: a gap of up to 0.3 m is one nosing split in two (the detector's split flights).
    EXPECT_TRUE(isSameStairEdge(left, right));
    MergeParams gap_small;
    gap_small.min_edge_overlap_m = -0.1;
    EXPECT_FALSE(isSameStairEdge(left, right, gap_small)) << "20 cm gap > 10 cm allowed";
    // The landmark map asks for overlap: collinear edges of side-by-side flights stay apart.
    MergeParams overlap;
    overlap.min_edge_overlap_m = 0.05;
    EXPECT_FALSE(isSameStairEdge(left, right, overlap));
    EXPECT_TRUE(isSameStairEdge(left, edgeAlongY(2.0, 0.2, -0.6), overlap)) << "15 cm overlap";
}

TEST(EdgeFusion, WeightsTheLinesByTheirCovariance) {
    StairEdge a = edgeAlongY(1.0, 1.0, -1.0), b = edgeAlongY(1.04, 1.0, -1.0);
    b.cov_rho_theta = Eigen::Vector2d(9e-4, 1e-4).asDiagonal();  // sigma 3 cm vs 1 cm
    const StairEdge f = fuseEdges(a, 1, b, 1, 0.0);
    EXPECT_NEAR(f.centre().x(), 1.0 + 0.04 * 0.1, 1e-6);  // information weights 9:1
    EXPECT_NEAR(f.cov_rho_theta(0, 0), 1.0 / (1.0 / 1e-4 + 1.0 / 9e-4), 1e-9);
    EXPECT_NEAR(f.length(), 2.0, 1e-9);
    EXPECT_EQ(f.num_points, 40);
}

TEST(EdgeFusion, FusedOrientationIsTheInformationWeightedMean) {
    // b is turned by 2 deg about its centre and as uncertain in theta as a: the result is at 1 deg.
    const StairEdge a = edgeAlongY(2.0, 0.6, -0.6);
    StairEdge b = a;
    const double t = std::tan(2.0 * M_PI / 180.0) * 0.6;
    b.start.x() -= t;
    b.end.x() += t;
    const StairEdge f = fuseEdges(a, 1, b, 1, 0.0);
    const double alpha = std::atan2(f.end.x() - f.start.x(), f.start.y() - f.end.y());
    EXPECT_NEAR(alpha * 180.0 / M_PI, 1.0, 0.02);
}

TEST(EdgeFusion, StartIsLeftOfTheHeadingWhateverTheInputSense) {
    const StairEdge a = edgeAlongY(1.0, 0.5, -0.5);
    const StairEdge reversed = edgeAlongY(1.0, -0.5, 0.5);
    const StairEdge up = fuseEdges(reversed, 1, a, 1, 0.0);  // facing +x, left is +y
    EXPECT_GT(up.start.y(), up.end.y());
    const StairEdge down = fuseEdges(a, 1, reversed, 1, M_PI);  // facing -x, left is -y
    EXPECT_LT(down.start.y(), down.end.y());
}

TEST(EdgeFusion, NearEndsAreAveragedByWeightFarEndsExtend) {
    const StairEdge landmark = edgeAlongY(0.0, 0.60, -0.60);
    // Right end 4 cm out (inside the 10 cm tolerance): averaged 3:1; left end 30 cm short:
    // a partial view never shortens the edge.
    const StairEdge partial = edgeAlongY(0.0, 0.30, -0.64);
    const StairEdge f = fuseEdges(landmark, 3, partial, 1, 0.0);
    EXPECT_NEAR(f.start.y(), 0.60, 1e-9);
    EXPECT_NEAR(f.end.y(), -0.61, 1e-9);
    // A longer view extends it.
    const StairEdge longer = edgeAlongY(0.0, 0.90, -0.60);
    EXPECT_NEAR(fuseEdges(landmark, 3, longer, 1, 0.0).start.y(), 0.90, 1e-9);
}

TEST(EdgeFusion, ZeroToleranceIsTheUnionOfExtents) {
    MergeParams union_only;
    union_only.endpoint_tolerance_m = 0.0;
    const StairEdge f =
        fuseEdges(edgeAlongY(0.0, 0.60, -0.60), 3, edgeAlongY(0.0, 0.55, -0.64), 1, 0.0, union_only);
    EXPECT_NEAR(f.start.y(), 0.60, 1e-9);
    EXPECT_NEAR(f.end.y(), -0.64, 1e-9);
}

TEST(EdgeFusion, HeightIsWeightedByPerpendicularVariance) {
    StairEdge a = edgeAlongY(1.0, 0.5, -0.5, 0.20), b = edgeAlongY(1.0, 0.5, -0.5, 0.23);
    b.cov_rho_theta(0, 0) = 4e-4;  // sigma 2 cm vs 1 cm: weights 4:1
    EXPECT_NEAR(fuseEdges(a, 1, b, 1, 0.0).centre().z(), 0.20 + 0.03 * 0.2, 1e-9);
}

TEST(EdgeFusion, CovarianceIsAboutTheFrameOriginWithPositiveRho) {
    // Edges along y at x = -2 centred 1 m off the x axis: rho = 2 (normal towards -x). About the
    // centre the fused line has var(rho) = var(theta) = 0.5e-4; moved 1 m along the line to the
    // frame origin's foot point, var(rho) gains 1^2 var(theta) and a cross term appears.
    const StairEdge a = edgeAlongY(-2.0, 0.5, 1.5), b = edgeAlongY(-2.0, 0.6, 1.4);
    const StairEdge f = fuseEdges(a, 1, b, 1, M_PI);
    EXPECT_NEAR(f.rhoTheta().x(), 2.0, 1e-9);
    EXPECT_NEAR(f.cov_rho_theta(0, 0), 1e-4, 1e-12);
    EXPECT_NEAR(f.cov_rho_theta(1, 1), 0.5e-4, 1e-12);
    EXPECT_NEAR(std::abs(f.cov_rho_theta(0, 1)), 0.5e-4, 1e-12);
}

TEST(EdgeFusion, SingularCovariancesAreFlooredNotInverted) {
    StairEdge a = edgeAlongY(1.0, 0.5, -0.5), b = edgeAlongY(1.01, 0.5, -0.5);
    a.cov_rho_theta.setZero();
    b.cov_rho_theta.setZero();
    const StairEdge f = fuseEdges(a, 1, b, 1, 0.0);
    ASSERT_TRUE(f.start.allFinite() && f.end.allFinite() && f.cov_rho_theta.allFinite());
    EXPECT_NEAR(f.centre().x(), 1.005, 1e-9);  // equal floors: the mean
}

}  // namespace
}  // namespace stairmap
