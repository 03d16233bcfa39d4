// Algorithm 2 (merging two detections of one staircase) on known flights.
#include <gtest/gtest.h>

#include <cmath>

#include "core/StaircaseGeometry.h"
#include "core/StaircaseMerge.h"

namespace stairmap {
namespace {

constexpr double kRise = 0.17, kRun = 0.28, kWidth = 1.2;

/// True nosings 0..n-1 of one flight going up along +x from x = 2 (world frame).
StairEdge nosing(int i, double lateral_lo = -kWidth / 2, double lateral_hi = kWidth / 2) {
    StairEdge e;
    const double x = 2.0 + i * kRun, z = (i + 1) * kRise;
    e.start << x, lateral_hi, z;  // left of the heading (+x) is +y
    e.end << x, lateral_lo, z;
    e.cov_rho_theta << 1e-4, 0.0, 0.0, 1e-3;
    e.num_points = 30;
    return e;
}

/// Ascending detection holding nosings [first, last].
Staircase ascending(int first, int last) {
    Staircase s;
    for (int i = first; i <= last; ++i) s.steps.push_back(nosing(i));
    estimateGeometry(s);
    return s;
}

TEST(StaircaseMerge, OverlappingDetectionsGiveTheUnion) {
    const auto m = mergeStaircases(ascending(0, 4), ascending(2, 7));
    ASSERT_TRUE(m.has_value());
    ASSERT_EQ(m->steps.size(), 8u);
    for (int i = 0; i < 8; ++i) EXPECT_LT((m->steps[i].centre() - nosing(i).centre()).norm(), 1e-6);
    EXPECT_NEAR(m->step_height, kRise, 1e-6);
    EXPECT_NEAR(m->step_depth, kRun, 1e-6);
}

TEST(StaircaseMerge, OneStepOverlapIsEnough) {
    const auto m = mergeStaircases(ascending(0, 3), ascending(3, 6));
    ASSERT_TRUE(m.has_value());
    EXPECT_EQ(m->steps.size(), 7u);
    EXPECT_TRUE(m->location.isApprox(nosing(0).centre()));
}

TEST(StaircaseMerge, SubsetAddsNothingAndOrderDoesNotMatter) {
    const auto m1 = mergeStaircases(ascending(0, 6), ascending(2, 4));
    const auto m2 = mergeStaircases(ascending(2, 4), ascending(0, 6));
    ASSERT_TRUE(m1 && m2);
    EXPECT_EQ(m1->steps.size(), 7u);
    EXPECT_EQ(m2->steps.size(), 7u);
    EXPECT_TRUE(m1->location.isApprox(m2->location));
}

TEST(StaircaseMerge, DisjointDetectionsDoNotMatch) {
    EXPECT_FALSE(mergeStaircases(ascending(0, 2), ascending(4, 6)).has_value());
    Staircase far = ascending(0, 3);
    for (auto& e : far.steps) {
        e.start.x() += 3.0;
        e.end.x() += 3.0;
    }
    EXPECT_FALSE(mergeStaircases(ascending(0, 3), far).has_value());
}

TEST(StaircaseMerge, MatchedEdgesAreFusedByCovarianceAndExtentsUnited) {
    Staircase a = ascending(0, 2), b = ascending(0, 2);
    // a sees the left half of step 1 and is 3 cm off; b sees the right half, exactly, and is sure.
    a.steps[1] = nosing(1, 0.0, kWidth / 2);
    a.steps[1].start.x() += 0.03;
    a.steps[1].end.x() += 0.03;
    a.steps[1].cov_rho_theta << 9e-4, 0, 0, 1e-3;
    b.steps[1] = nosing(1, -kWidth / 2, 0.0);
    b.steps[1].cov_rho_theta << 1e-6, 0, 0, 1e-3;
    const auto m = mergeStaircases(a, b);
    ASSERT_TRUE(m.has_value());
    const StairEdge& e = m->steps[1];
    EXPECT_NEAR(e.centre().x(), nosing(1).centre().x(), 0.001) << "pulled to the certain edge";
    EXPECT_NEAR(e.length(), kWidth, 0.002) << "union of both halves";
    EXPECT_LT(e.cov_rho_theta(0, 0), 1e-6 + 1e-9);
    EXPECT_EQ(e.num_points, 60);
}

TEST(StaircaseMerge, SeenFromBelowAndFromAboveMergeInCanonicalForm) {
    // From the top floor looking down: nosings 7 (top landing edge) .. 3, descending.
    Staircase down;
    down.direction = StairDirection::Descending;
    for (int i = 7; i >= 3; --i) {
        StairEdge e = nosing(i);
        std::swap(e.start, e.end);  // facing -x, left is -y
        down.steps.push_back(e);
    }
    estimateGeometry(down);
    EXPECT_NEAR(std::abs(down.heading_rad), M_PI, 1e-9);
    const Staircase up = ascending(0, 4);
    EXPECT_THROW(mergeStaircases(up, down), std::invalid_argument);
    const auto m = mergeStaircases(toBottomUp(up), toBottomUp(down));
    ASSERT_TRUE(m.has_value());
    ASSERT_EQ(m->steps.size(), 8u);
    EXPECT_EQ(m->direction, StairDirection::Ascending);
    EXPECT_NEAR(m->heading_rad, 0.0, 1e-9);
    for (int i = 0; i < 8; ++i) EXPECT_LT((m->steps[i].centre() - nosing(i).centre()).norm(), 1e-6);
}

TEST(StaircaseMerge, DefinitionTwoThresholds) {
    StairEdge a = nosing(0), b = nosing(0);
    EXPECT_TRUE(isSameStairEdge(a, b));
    b.start.z() += 0.06;
    b.end.z() += 0.06;
    EXPECT_FALSE(isSameStairEdge(a, b)) << "height differs by more than 5 cm";
    b = nosing(0);
    b.start.x() += 0.06;
    b.end.x() += 0.06;
    EXPECT_FALSE(isSameStairEdge(a, b)) << "lines 6 cm apart";
    b = nosing(0);
    b.end.x() += std::tan(12.0 * M_PI / 180.0) * kWidth;
    EXPECT_FALSE(isSameStairEdge(a, b)) << "12 deg apart";
}

}  // namespace
}  // namespace stairmap
