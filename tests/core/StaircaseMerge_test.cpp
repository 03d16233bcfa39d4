// Algorithm 2 (merging two detections of one staircase) on known flights: the cases of the
// detector (split flights, plain detections) and of the landmark map (weighted canonical views,
// level pairing, gaps, drift), with exact geometry and seeded noise.
#include <gtest/gtest.h>

#include <cmath>

#include "core/StaircaseCanonical.h"
#include "core/StaircaseGeometry.h"
#include "core/StaircaseMerge.h"
#include "core/SyntheticStairs.h"

namespace stairmap {
namespace {

using test::FlightTruth;
using test::makeDetection;
using test::ViewSpec;

/// Exact detection of edges [first, last] of `truth` (-1: the top), as the detector orders them.
Staircase exact(const FlightTruth& truth, int first, int last, bool descending = false) {
    std::mt19937 rng(0);
    ViewSpec v;
    v.first = first;
    v.last = last;
    v.descending = descending;
    Staircase s = makeDetection(truth, v, rng);
    estimateGeometry(s);
    return s;
}

WeightedStaircase weighted(const Staircase& s) {
    const Staircase c = *canonicalStaircase(s);
    return {c, std::vector<int>(c.steps.size(), 1)};
}

void expectEdgesAtTruth(const Staircase& s, const FlightTruth& truth, int first, double tol) {
    for (std::size_t i = 0; i < s.steps.size(); ++i) {
        const Eigen::Vector3d c = truth.edgeCentre(first + static_cast<int>(i));
        EXPECT_LT((s.steps[i].centre() - c).norm(), tol) << "step " << i;
    }
}

TEST(StaircaseMerge, OverlappingDetectionsGiveTheUnionOfSteps) {
    const FlightTruth truth;
    const auto m = mergeStaircases(exact(truth, 0, 4), exact(truth, 2, 7));
    ASSERT_TRUE(m.has_value());
    ASSERT_EQ(m->steps.size(), 8u);
    expectEdgesAtTruth(*m, truth, 0, 1e-9);
    EXPECT_NEAR(m->step_height, truth.rise, 1e-9);
    EXPECT_NEAR(m->step_depth, truth.run, 1e-9);
    EXPECT_NEAR(m->step_width, truth.width, 1e-9);
}

TEST(StaircaseMerge, OneCommonStepIsEnoughAndOrderDoesNotMatter) {
    const FlightTruth truth;
    const auto m1 = mergeStaircases(exact(truth, 0, 3), exact(truth, 3, 6));
    const auto m2 = mergeStaircases(exact(truth, 3, 6), exact(truth, 0, 3));
    ASSERT_TRUE(m1 && m2);
    EXPECT_EQ(m1->steps.size(), 7u);
    EXPECT_EQ(m2->steps.size(), 7u);
    EXPECT_TRUE(m1->location.isApprox(truth.edgeCentre(0), 1e-9));
    EXPECT_TRUE(m2->location.isApprox(truth.edgeCentre(0), 1e-9));
    const auto subset = mergeStaircases(exact(truth, 0, 6), exact(truth, 2, 4));
    ASSERT_TRUE(subset.has_value());
    EXPECT_EQ(subset->steps.size(), 7u);
}

TEST(StaircaseMerge, NoCommonStepIsNoMatch) {
    const FlightTruth truth;
    EXPECT_FALSE(haveCommonStair(exact(truth, 0, 2), exact(truth, 4, 6)));
    EXPECT_TRUE(haveCommonStair(exact(truth, 0, 2), exact(truth, 2, 6)));
    EXPECT_FALSE(mergeStaircases(exact(truth, 0, 2), exact(truth, 4, 6)).has_value());
    FlightTruth elsewhere = truth;
    elsewhere.origin_xy = {3.0, 0.0};
    EXPECT_FALSE(mergeStaircases(exact(truth, 0, 3), exact(elsewhere, 0, 3)).has_value());
    const WeightedStaircase a = weighted(exact(truth, 0, 2)), b = weighted(exact(truth, 4, 6));
    EXPECT_FALSE(mergeCanonical(a, b, MergeParams{}).has_value());
}

TEST(StaircaseMerge, AMissedNosingDoesNotShiftTheLaterSteps) {
    // a missed step 3 (occluded): pairing by index from the first match would fuse a's step 4 with
    // b's step 3; pairing by level fuses each step with itself.
    const FlightTruth truth;
    Staircase a = exact(truth, 0, 6);
    a.steps.erase(a.steps.begin() + 3);
    const Staircase b = exact(truth, 0, 6);
    const auto m = mergeCanonical(weighted(a), weighted(b), MergeParams{});
    ASSERT_TRUE(m.has_value());
    ASSERT_EQ(m->stairs.steps.size(), 7u);
    expectEdgesAtTruth(m->stairs, truth, 0, 1e-9);
    EXPECT_EQ(m->step_observations, (std::vector<int>{2, 2, 2, 1, 2, 2, 2}));
    const auto plain = mergeStaircases(a, b);
    ASSERT_TRUE(plain.has_value());
    ASSERT_EQ(plain->steps.size(), 7u);
    expectEdgesAtTruth(*plain, truth, 0, 1e-9);
}

TEST(StaircaseMerge, DriftWithinDefinitionTwoMeetsHalfWay) {
    // b drifted 4 cm up (within Definition 2) and 2 cm sideways: steps still pair with themselves
    // and meet half way (equal covariances, equal weights).
    const FlightTruth truth;
    Staircase b = exact(truth, 2, 8);
    for (StairEdge& e : b.steps) {
        e.start += Eigen::Vector3d(0.02, 0.0, 0.04);
        e.end += Eigen::Vector3d(0.02, 0.0, 0.04);
    }
    const auto m = mergeCanonical(weighted(exact(truth, 0, 5)), weighted(b), MergeParams{});
    ASSERT_TRUE(m.has_value());
    ASSERT_EQ(m->stairs.steps.size(), 9u);
    EXPECT_EQ(m->step_observations, (std::vector<int>{1, 1, 2, 2, 2, 2, 1, 1, 1}));
    EXPECT_NEAR(m->stairs.steps[3].centre().z(), truth.edgeCentre(3).z() + 0.02, 1e-9);
    EXPECT_NEAR(m->stairs.steps[3].centre().x(), truth.edgeCentre(3).x() + 0.01, 1e-9);
}

TEST(StaircaseMerge, AssociatedFlightsPairByLevelEvenBeyondDefinitionTwo) {
    // 15 cm of xy drift: no pair is the same stair (the landmark map associated them by footprint).
    const FlightTruth truth;
    Staircase b = exact(truth, 3, 6);
    for (StairEdge& e : b.steps) {
        e.start.x() += 0.15;
        e.end.x() += 0.15;
    }
    const WeightedStaircase wa = weighted(exact(truth, 0, 4)), wb = weighted(b);
    EXPECT_FALSE(mergeCanonical(wa, wb, MergeParams{}).has_value()) << "Algorithm 2: NO_MATCH";
    const auto m = mergeCanonical(wa, wb, MergeParams{}, StepAnchor::AssociatedElsewhere);
    ASSERT_TRUE(m.has_value());
    ASSERT_EQ(m->stairs.steps.size(), 7u);
    for (int i = 0; i < 7; ++i)
        EXPECT_NEAR(m->stairs.steps[i].centre().z(), truth.edgeCentre(i).z(), 1e-9);
    EXPECT_EQ(m->step_observations, (std::vector<int>{1, 1, 1, 2, 2, 1, 1}));
}

TEST(StaircaseMerge, GapBetweenBottomAndTopViewsIsKeptNotInvented) {
    FlightTruth truth;
    truth.num_steps = 16;
    const auto m = mergeCanonical(weighted(exact(truth, 0, 3)), weighted(exact(truth, 11, -1, true)),
                                  MergeParams{}, StepAnchor::AssociatedElsewhere);
    ASSERT_TRUE(m.has_value());
    ASSERT_EQ(m->stairs.steps.size(), 9u);  // 4 + 5 seen; the 7 never seen stay absent
    EXPECT_NEAR(m->stairs.step_height, truth.rise, 1e-9);
    EXPECT_NEAR(m->stairs.step_depth, truth.run, 1e-9);
    EXPECT_NEAR(m->stairs.steps.back().centre().z(), truth.topZ(), 1e-9);
    EXPECT_TRUE(m->stairs.location.isApprox(truth.edgeCentre(0), 1e-9));
}

TEST(StaircaseMerge, SeenFromBelowAndFromAboveMergeInCanonicalForm) {
    FlightTruth truth;
    truth.heading_rad = 2.5;
    const Staircase up = exact(truth, 0, 4), down = exact(truth, 3, 7, true);
    EXPECT_THROW(mergeStaircases(up, down), std::invalid_argument);
    EXPECT_THROW(mergeCanonical({down, std::vector<int>(down.steps.size(), 1)}, weighted(up),
                                MergeParams{}),
                 std::invalid_argument);
    const auto m = mergeCanonical(weighted(up), weighted(down), MergeParams{});
    ASSERT_TRUE(m.has_value());
    ASSERT_EQ(m->stairs.steps.size(), 8u);
    EXPECT_EQ(m->stairs.direction, StairDirection::Ascending);
    EXPECT_NEAR(m->stairs.heading_rad, 2.5, 1e-9);
    expectEdgesAtTruth(m->stairs, truth, 0, 1e-9);
    for (const StairEdge& e : m->stairs.steps)
        EXPECT_GT((e.start - e.end).head<2>().dot(truth.left()), 0.0) << "start left facing uphill";
}

TEST(StaircaseMerge, SplitDescendingFlightKeepsItsOrderAndFullWidth) {
    // The detector's case: one flight seen from the top as two side-by-side chains, each nosing
    // split by a 20 cm occlusion. Merged: steps still top to bottom, edges full width again.
    FlightTruth truth;
    truth.heading_rad = -1.0;
    std::mt19937 rng(0);
    ViewSpec left, right;
    left.descending = right.descending = true;
    left.crop_right = 0.7;  // keeps the left 0.5 m
    right.crop_left = 0.7;  // keeps the right 0.5 m
    Staircase a = makeDetection(truth, left, rng), b = makeDetection(truth, right, rng);
    estimateGeometry(a);
    estimateGeometry(b);
    const auto m = mergeStaircases(a, b);
    ASSERT_TRUE(m.has_value());
    ASSERT_EQ(m->steps.size(), static_cast<std::size_t>(truth.num_steps));
    EXPECT_EQ(m->direction, StairDirection::Descending);
    for (int k = 0; k < truth.num_steps; ++k) {
        const StairEdge& e = m->steps[k];
        EXPECT_NEAR(e.centre().z(), truth.edgeCentre(truth.num_steps - 1 - k).z(), 1e-9);
        EXPECT_NEAR(e.length(), truth.width, 1e-9) << "union of the two halves";
        EXPECT_LT((e.start - e.end).head<2>().dot(truth.left()), 0.0) << "start left facing downhill";
    }
    EXPECT_NEAR(m->step_width, truth.width, 1e-9);
    EXPECT_NEAR(std::remainder(m->heading_rad - (truth.heading_rad + M_PI), 2 * M_PI), 0.0, 1e-9);
}

TEST(StaircaseMerge, ADuplicateInOneDetectionNeverDoublesAStep) {
    const FlightTruth truth;
    Staircase b = exact(truth, 0, 1);
    StairEdge twin = b.steps[1];
    twin.start.z() += 0.01;
    twin.end.z() += 0.01;
    b.steps.push_back(twin);  // the same nosing twice (no a step left to pair it with)
    const auto m = mergeCanonical(weighted(exact(truth, 0, 1)), weighted(b), MergeParams{});
    ASSERT_TRUE(m.has_value());
    ASSERT_EQ(m->stairs.steps.size(), 2u);
    EXPECT_EQ(m->step_observations, (std::vector<int>{2, 3}));
}

TEST(StaircaseMerge, BadInputThrowsNamingTheProblem) {
    const FlightTruth truth;
    MergeParams bad;
    bad.max_angle_deg = 0.0;
    try {
        mergeStaircases(exact(truth, 0, 3), exact(truth, 0, 3), bad);
        FAIL() << "no throw";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("max_angle_deg"), std::string::npos) << e.what();
    }
    WeightedStaircase w = weighted(exact(truth, 0, 3));
    w.step_observations.pop_back();
    EXPECT_THROW(mergeCanonical(w, weighted(exact(truth, 0, 3)), MergeParams{}),
                 std::invalid_argument);
}

TEST(StaircaseMerge, SidesSurviveMergingAndFollowTheCanonicalHeading) {
    const FlightTruth truth;
    Staircase a = exact(truth, 0, 4), b = exact(truth, 2, 7);
    a.right_side = StairSide::Open;  // a saw the right side, b the left one
    b.left_side = StairSide::Wall;
    const auto m = mergeStaircases(a, b);
    ASSERT_TRUE(m.has_value());
    EXPECT_EQ(m->left_side, StairSide::Wall);
    EXPECT_EQ(m->right_side, StairSide::Open);
    // seen from above, left and right are taken looking downhill: canonical (uphill) swaps them
    Staircase down = exact(truth, 0, 4, true);
    down.left_side = StairSide::Wall;
    down.right_side = StairSide::Open;
    const Staircase c = *canonicalStaircase(down);
    EXPECT_EQ(c.left_side, StairSide::Open);
    EXPECT_EQ(c.right_side, StairSide::Wall);
}

}  // namespace
}  // namespace stairmap
