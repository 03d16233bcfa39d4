// Segmentation stage: weighted line fit, iterative end-point split, seam crossing.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "core/LineFit.h"
#include "core/RowSegmentation.h"

namespace stairmap {
namespace {

struct Row {
    std::vector<float> x, y, z;
    void add(double px, double py, double pz = 0.0) {
        x.push_back(static_cast<float>(px));
        y.push_back(static_cast<float>(py));
        z.push_back(static_cast<float>(pz));
    }
    RowPointView view() const { return {x.data(), y.data(), z.data()}; }
    int size() const { return static_cast<int>(x.size()); }
};

TEST(LineFit, ExactPointsGiveExactHessianParameters) {
    // Line x = 2 (normal +x, rho = 2), points from y = -0.5 to 0.5 at z = 0.3.
    Row row;
    for (int i = 0; i <= 20; ++i) row.add(2.0, -0.5 + 0.05 * i, 0.3);
    const LineSegment l = fitLine(row.view(), 0, row.size() - 1, 0.01);
    EXPECT_NEAR(l.rho, 2.0, 1e-6);
    EXPECT_NEAR(std::remainder(l.theta, 2 * M_PI), 0.0, 1e-6);
    EXPECT_NEAR(l.z, 0.3, 1e-6);
    EXPECT_NEAR(l.length(), 1.0, 1e-6) << "end points are the projected first and last points";
    EXPECT_EQ(l.num_points, 21);
}

TEST(LineFit, ObliqueLineThroughKnownPoints) {
    // Line with normal at 135 deg and rho = 1: points p = rho*n + t*u.
    const double th = 135.0 * M_PI / 180.0;
    const Eigen::Vector2d n(std::cos(th), std::sin(th)), u(-n.y(), n.x());
    Row row;
    for (int i = 0; i < 30; ++i) {
        const Eigen::Vector2d p = 1.0 * n + (-0.6 + 0.04 * i) * u;
        row.add(p.x(), p.y());
    }
    const LineSegment l = fitLine(row.view(), 0, row.size() - 1, 0.01);
    EXPECT_NEAR(l.rho, 1.0, 1e-6);
    EXPECT_NEAR(std::remainder(l.theta - th, 2 * M_PI), 0.0, 1e-6);
}

TEST(LineFit, CovarianceIsSaneAndShrinksWithSupport) {
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0.0, 0.01);
    auto fitN = [&](int n, double len) {
        Row row;
        for (int i = 0; i < n; ++i) row.add(3.0 + noise(rng), -len / 2 + len * i / (n - 1));
        return fitLine(row.view(), 0, n - 1, 0.01);
    };
    const LineSegment small = fitN(10, 0.5), big = fitN(80, 2.0);
    for (const LineSegment* l : {&small, &big}) {
        EXPECT_GT(l->cov(0, 0), 0.0);
        EXPECT_GT(l->cov(1, 1), 0.0);
        EXPECT_GT(l->cov.determinant(), 0.0) << "positive definite";
        EXPECT_NEAR(l->cov(0, 1), l->cov(1, 0), 1e-15);
    }
    EXPECT_LT(big.cov(1, 1), small.cov(1, 1) / 10) << "longer, denser line: far smaller var(theta)";
    // var(theta) ~ sigma^2 / sum(t^2): 1e-4 / (10 * 0.5^2 * 11/108) ~ 3.9e-4
    EXPECT_NEAR(small.cov(1, 1), 3.9e-4, 2.5e-4);
}

TEST(LineFit, RhoThetaCorrelationFollowsTheCentroid) {
    // Points far along the line from the foot of the normal: rho at the origin depends strongly on
    // theta (d rho / d theta = centroid . n'(theta) = 1.5 m here), positive correlation.
    Row row;
    for (int i = 0; i < 41; ++i) row.add(2.0, 1.0 + 0.025 * i);
    const LineSegment l = fitLine(row.view(), 0, 40, 0.01);
    const double corr = l.cov(0, 1) / std::sqrt(l.cov(0, 0) * l.cov(1, 1));
    EXPECT_GT(corr, 0.9);
    EXPECT_NEAR(l.cov(0, 1) / l.cov(1, 1), 1.5, 1e-6);
}

TEST(LineFit, MahalanobisSeparatesSameFromDifferentLines) {
    Row a, b, c;
    for (int i = 0; i < 20; ++i) {
        a.add(2.0, -1.0 + 0.025 * i);
        b.add(2.0, 0.0 + 0.025 * i);
        c.add(2.15, 0.0 + 0.025 * i);
    }
    const auto la = fitLine(a.view(), 0, 19, 0.01);
    const auto lb = fitLine(b.view(), 0, 19, 0.01);
    const auto lc = fitLine(c.view(), 0, 19, 0.01);
    EXPECT_LT(lineMahalanobis2(la, lb), 9.21);
    EXPECT_GT(lineMahalanobis2(la, lc), 9.21);
}

SegmentationParams testParams() {
    SegmentationParams p;
    p.min_line_points = 4;
    p.min_line_length_m = 0.1;
    return p;
}

TEST(RowSegmentation, SplitsAKnownRowIntoItsEdgesKeepingTheCorner) {
    // An L seen from the origin: edge x = 2 for y in [-1, 0], then y = 0 for x in [2, 3].
    Row row;
    for (int i = 0; i <= 40; ++i) row.add(2.0, -1.0 + 0.025 * i);
    for (int i = 1; i <= 40; ++i) row.add(2.0 + 0.025 * i, 0.0);
    std::vector<LineSegment> lines;
    segmentCircularRow(row.x.data(), row.y.data(), row.z.data(), row.size(), testParams(), lines);
    ASSERT_EQ(lines.size(), 2u);
    // Both lines reach the corner (2, 0): the split point is not dropped.
    const Eigen::Vector2d corner(2.0, 0.0);
    for (const auto& l : lines) {
        const double d = std::min((l.start - corner).norm(), (l.end - corner).norm());
        EXPECT_LT(d, 1e-3);
    }
    EXPECT_NEAR(lines[0].length() + lines[1].length(), 2.0, 1e-3);
}

TEST(RowSegmentation, LineCrossingTheSeamBehindTheRobotStaysWhole) {
    // Edge x = -2 from y = -0.6 to 0.6, directly behind the robot. In azimuth order
    // ([-180, 180)) the row starts at y < 0 (azimuth just above -180) and ends at y > 0.
    Row row;
    for (int i = 0; i <= 24; ++i) row.add(-2.0, -0.025 * i);        // azimuth -180 .. -173
    for (int i = 0; i < 50; ++i) row.add(2.0, -1.0 + 0.04 * i);     // something in front
    for (int i = 24; i >= 1; --i) row.add(-2.0, 0.025 * i);         // azimuth 173 .. 180
    std::vector<LineSegment> lines;
    segmentCircularRow(row.x.data(), row.y.data(), row.z.data(), row.size(), testParams(), lines);
    int behind = 0;
    for (const auto& l : lines) {
        if (l.centre().x() < 0) {
            ++behind;
            EXPECT_NEAR(l.length(), 1.2, 0.03) << "the seam must not cut the edge";
            EXPECT_NEAR(l.rho, 2.0, 1e-3);
        }
    }
    EXPECT_EQ(behind, 1);
}

TEST(RowSegmentation, SinglePointSpikeDoesNotCutAnEdge) {
    Row row;
    for (int i = 0; i <= 40; ++i) row.add(i == 20 ? 2.15 : 2.0, -0.5 + 0.025 * i);
    std::vector<LineSegment> lines;
    segmentCircularRow(row.x.data(), row.y.data(), row.z.data(), row.size(), testParams(), lines);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_NEAR(lines[0].length(), 1.0, 1e-3);
}

TEST(RowSegmentation, GapsSeparateCollinearPieces) {
    Row row;
    for (int i = 0; i <= 20; ++i) row.add(2.0, -1.0 + 0.025 * i);  // y in [-1, -0.5]
    for (int i = 0; i <= 20; ++i) row.add(2.0, 0.5 + 0.025 * i);   // y in [0.5, 1]
    std::vector<LineSegment> lines;
    segmentCircularRow(row.x.data(), row.y.data(), row.z.data(), row.size(), testParams(), lines);
    EXPECT_EQ(lines.size(), 2u);
}

TEST(RowSegmentation, TooFewPointsGiveNoLine) {
    Row row;
    for (int i = 0; i < 3; ++i) row.add(2.0, 0.1 * i);
    std::vector<LineSegment> lines;
    segmentCircularRow(row.x.data(), row.y.data(), row.z.data(), row.size(), testParams(), lines);
    EXPECT_TRUE(lines.empty());
}

}  // namespace
}  // namespace stairmap
