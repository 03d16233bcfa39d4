// Association, canonical form, bridging, confirmation and robustness of the landmark map, on
// synthetic detections with known geometry.
#include <gtest/gtest.h>

#include "map/LandmarkMap.h"
#include "core/StaircaseCanonical.h"
#include "core/SyntheticStairs.h"

namespace stairmap {
namespace {

using test::FlightTruth;
using test::makeDetection;
using test::ViewSpec;

ViewSpec noisy(int first, int last) {
    ViewSpec v;
    v.first = first;
    v.last = last;
    v.sigma_perp = 0.01;
    v.sigma_theta = 0.01;
    v.sigma_z = 0.008;
    v.sigma_end = 0.02;
    return v;
}

TEST(StaircaseCanonical, DescendingDetectionBecomesAscendingBottomToTop) {
    FlightTruth truth;
    truth.heading_rad = 0.7;
    truth.origin_xy = {2.0, -1.0};
    std::mt19937 rng(1);
    ViewSpec view;
    view.descending = true;
    const Staircase det = makeDetection(truth, view, rng);
    ASSERT_GT(det.steps.front().centre().z(), det.steps.back().centre().z());
    const auto c = canonicalStaircase(det);
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->direction, StairDirection::Ascending);
    EXPECT_NEAR(c->heading_rad, 0.7, 1e-9);
    EXPECT_TRUE(c->location.isApprox(truth.edgeCentre(0), 1e-9));
    for (std::size_t i = 0; i < c->steps.size(); ++i) {
        EXPECT_NEAR(c->steps[i].centre().z(), truth.edgeCentre(static_cast<int>(i)).z(), 1e-9);
        // start is the left end when facing uphill
        EXPECT_GT((c->steps[i].start - c->steps[i].end).head<2>().dot(truth.left()), 0.0);
    }
    EXPECT_NEAR(c->step_height, truth.rise, 1e-9);
    EXPECT_NEAR(c->step_depth, truth.run, 1e-9);
    EXPECT_NEAR(c->step_width, truth.width, 1e-9);
}

TEST(LandmarkMap, PartialViewsFromSeveralViewpointsGiveOneLandmark) {
    FlightTruth truth;
    truth.heading_rad = -2.0;
    truth.origin_xy = {5.0, 3.0};
    LandmarkMap map;
    std::mt19937 rng(2);
    std::vector<ViewSpec> views = {noisy(0, 3), noisy(2, 6), noisy(5, 9), noisy(0, 9)};
    views[1].crop_left = 0.5;   // the left half hidden by a wall
    views[2].crop_right = 0.4;
    views[2].descending = true;
    for (std::size_t i = 0; i < views.size(); ++i) {
        const LandmarkUpdate u = map.addDetection(makeDetection(truth, views[i], rng), i * 1.0);
        EXPECT_EQ(u.landmark_id, 0) << "view " << i;
        EXPECT_EQ(u.created, i == 0) << "view " << i;
    }
    ASSERT_EQ(map.staircases().size(), 1u);
    const StaircaseLandmark& lm = map.staircases()[0];
    EXPECT_EQ(lm.stairs.steps.size(), 10u);
    EXPECT_EQ(lm.observations, 4);
    EXPECT_NEAR(lm.stairs.step_width, truth.width, 0.05);
    EXPECT_LT((lm.stairs.location - truth.edgeCentre(0)).norm(), 0.03);
    EXPECT_DOUBLE_EQ(lm.first_seen_s, 0.0);
    EXPECT_DOUBLE_EQ(lm.last_seen_s, 3.0);
}

TEST(LandmarkMap, AscendingFromBottomAndDescendingFromTopMerge) {
    FlightTruth truth;
    truth.heading_rad = 1.2;
    LandmarkMap map;
    std::mt19937 rng(3);
    ViewSpec from_bottom = noisy(0, 5);
    ViewSpec from_top = noisy(4, 9);
    from_top.descending = true;
    map.addDetection(makeDetection(truth, from_bottom, rng), 0.0);
    const LandmarkUpdate u = map.addDetection(makeDetection(truth, from_top, rng), 1.0);
    EXPECT_FALSE(u.created);
    ASSERT_EQ(map.staircases().size(), 1u);
    const Staircase& s = map.staircases()[0].stairs;
    EXPECT_EQ(s.steps.size(), 10u);
    EXPECT_NEAR(s.heading_rad, 1.2, 0.03);
    EXPECT_NEAR(s.steps.back().centre().z(), truth.topZ(), 0.03);
}

TEST(LandmarkMap, SideBySideFlightsStaySeparate) {
    FlightTruth a;  // two parallel flights at equal heights with collinear edges, 15 cm apart
    FlightTruth b = a;
    b.origin_xy = a.origin_xy + (a.width + 0.15) * a.left();
    LandmarkMap map;
    std::mt19937 rng(4);
    for (int k = 0; k < 5; ++k) {
        map.addDetection(makeDetection(a, noisy(0, 9), rng), k);
        map.addDetection(makeDetection(b, noisy(0, 9), rng), k + 0.5);
    }
    ASSERT_EQ(map.staircases().size(), 2u);
    EXPECT_EQ(map.staircases()[0].observations, 5);
    EXPECT_EQ(map.staircases()[1].observations, 5);
}

TEST(LandmarkMap, StackedFlightsOnDifferentFloorsStaySeparate) {
    FlightTruth lower;
    FlightTruth upper = lower;  // same stairwell, one floor up
    upper.floor_z = lower.topZ();
    LandmarkMap map;
    std::mt19937 rng(5);
    for (int k = 0; k < 4; ++k) {
        map.addDetection(makeDetection(lower, noisy(0, 9), rng), k);
        map.addDetection(makeDetection(upper, noisy(0, 9), rng), k + 0.5);
    }
    ASSERT_EQ(map.staircases().size(), 2u);
    EXPECT_NEAR(map.staircases()[0].stairs.location.z(), lower.edgeCentre(0).z(), 0.02);
    EXPECT_NEAR(map.staircases()[1].stairs.location.z(), upper.edgeCentre(0).z(), 0.02);
}

TEST(LandmarkMap, DriftedDetectionAssociatesByFootprint) {
    FlightTruth truth;
    LandmarkMap map;
    std::mt19937 rng(6);
    map.addDetection(makeDetection(truth, noisy(0, 9), rng), 0.0);
    ViewSpec drifted = noisy(0, 9);
    drifted.drift = {0.12, 0.1, 0.03};  // beyond the Definition-2 distance gate
    const LandmarkUpdate u = map.addDetection(makeDetection(truth, drifted, rng), 1.0);
    EXPECT_FALSE(u.created);
    EXPECT_EQ(map.staircases().size(), 1u);
    EXPECT_EQ(map.staircases()[0].stairs.steps.size(), 10u);

    LandmarkParams no_footprint;
    no_footprint.use_footprint = false;
    LandmarkMap strict(no_footprint);
    strict.addDetection(makeDetection(truth, noisy(0, 9), rng), 0.0);
    EXPECT_TRUE(strict.addDetection(makeDetection(truth, drifted, rng), 1.0).created);
}

TEST(LandmarkMap, BridgingDetectionJoinsTwoLandmarksKeepingTheOlderId) {
    FlightTruth truth;
    LandmarkParams params;
    params.use_footprint = false;
    params.max_extrapolated_steps = 0;  // so that the two partial views start apart
    LandmarkMap map(params);
    std::mt19937 rng(7);
    EXPECT_EQ(map.addDetection(makeDetection(truth, noisy(0, 2), rng), 0.0).landmark_id, 0);
    EXPECT_EQ(map.addDetection(makeDetection(truth, noisy(7, 9), rng), 1.0).landmark_id, 1);
    ASSERT_EQ(map.staircases().size(), 2u);
    const LandmarkUpdate u = map.addDetection(makeDetection(truth, noisy(1, 8), rng), 2.0);
    EXPECT_EQ(u.landmark_id, 0);
    EXPECT_TRUE(u.merged_landmarks);
    EXPECT_EQ(u.absorbed_ids, std::vector<int>{1});
    ASSERT_EQ(map.staircases().size(), 1u);
    EXPECT_EQ(map.staircases()[0].stairs.steps.size(), 10u);
    EXPECT_EQ(map.staircases()[0].observations, 3);
    ASSERT_NE(map.find(1), nullptr);
    EXPECT_EQ(map.find(1)->id, 0);
    // IDs are never reused: the next new landmark gets 2.
    FlightTruth elsewhere = truth;
    elsewhere.origin_xy = {20.0, 0.0};
    EXPECT_EQ(map.addDetection(makeDetection(elsewhere, noisy(0, 9), rng), 3.0).landmark_id, 2);
}

TEST(LandmarkMap, ConfirmedAfterKObservations) {
    LandmarkParams params;
    params.confirm_observations = 3;
    LandmarkMap map(params);
    FlightTruth truth;
    std::mt19937 rng(8);
    for (int k = 1; k <= 4; ++k) {
        map.addDetection(makeDetection(truth, noisy(0, 9), rng), k);
        ASSERT_EQ(map.staircases().size(), 1u);
        EXPECT_EQ(map.staircases()[0].observations, k);
        EXPECT_EQ(map.staircases()[0].confirmed, k >= 3) << "after " << k << " observations";
    }
}

TEST(LandmarkMap, AFlightOfFewerThanMinStepsIsNeverConfirmed) {
    LandmarkParams params;
    params.confirm_observations = 3;
    params.confirm_min_steps = 4;
    LandmarkMap map(params);
    FlightTruth stage;
    stage.num_steps = 3;  // a 2-step stage and its platform edge: three nosings
    std::mt19937 rng(9);
    for (int k = 1; k <= 6; ++k) map.addDetection(makeDetection(stage, noisy(0, 2), rng), k);
    ASSERT_EQ(map.staircases().size(), 1u);
    EXPECT_EQ(map.staircases()[0].observations, 6);
    EXPECT_FALSE(map.staircases()[0].confirmed);
    FlightTruth flight;  // the same seen with four nosings is confirmed after K observations
    flight.origin_xy = {10.0, 0.0};
    for (int k = 1; k <= 3; ++k) map.addDetection(makeDetection(flight, noisy(0, 3), rng), 10 + k);
    ASSERT_EQ(map.staircases().size(), 2u);
    EXPECT_TRUE(map.staircases()[1].confirmed);
}

TEST(LandmarkMap, RepeatedObservationsNeitherGrowStepsNorDrift) {
    FlightTruth truth;
    truth.origin_xy = {-3.0, 7.0};
    truth.heading_rad = 2.5;
    LandmarkMap map;
    std::mt19937 rng(9);
    for (int k = 0; k < 60; ++k) {
        ViewSpec v = noisy(k % 3, 9 - k % 2);  // slightly different partial views
        map.addDetection(makeDetection(truth, v, rng), k);
    }
    ASSERT_EQ(map.staircases().size(), 1u);
    const Staircase& s = map.staircases()[0].stairs;
    EXPECT_EQ(s.steps.size(), 10u);
    EXPECT_LT((s.location - truth.edgeCentre(0)).norm(), 0.01);
    EXPECT_LT((s.steps.back().centre() - truth.edgeCentre(9)).norm(), 0.01);
    EXPECT_NEAR(s.step_width, truth.width, 0.03);
}

TEST(LandmarkMap, RejectsEmptyAndNonFiniteDetections) {
    LandmarkMap map;
    EXPECT_FALSE(map.addDetection(Staircase{}, 0.0).changed);
    FlightTruth truth;
    std::mt19937 rng(10);
    Staircase bad = makeDetection(truth, ViewSpec{}, rng);
    bad.steps[2].end.x() = std::nan("");
    EXPECT_FALSE(map.addDetection(bad, 0.0).changed);
    EXPECT_TRUE(map.staircases().empty());
}

TEST(LandmarkMap, InvalidParamsNameTheField) {
    LandmarkParams p;
    p.confirm_observations = 0;
    try {
        LandmarkMap map(p);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("confirm_observations"), std::string::npos);
    }
}

}  // namespace
}  // namespace stairmap

namespace stairmap {
namespace {

TEST(LandmarkMap, BridgeOfPartialLandmarksGivesOneEdgePerStep) {
    // Two landmarks of one flight whose step indices disagree (each saw a different first step)
    // are joined: the result has one edge per physical step.
    test::FlightTruth truth;
    LandmarkParams params;
    params.use_footprint = false;
    params.max_extrapolated_steps = 0;
    LandmarkMap map(params);
    std::mt19937 rng(31);
    test::ViewSpec lower;
    lower.first = 0;
    lower.last = 4;
    test::ViewSpec upper;
    upper.first = 6;
    upper.last = 9;
    map.addDetection(test::makeDetection(truth, lower, rng), 0.0);
    map.addDetection(test::makeDetection(truth, upper, rng), 1.0);
    ASSERT_EQ(map.staircases().size(), 2u);
    test::ViewSpec middle;
    middle.first = 3;
    middle.last = 7;
    map.addDetection(test::makeDetection(truth, middle, rng), 2.0);
    ASSERT_EQ(map.staircases().size(), 1u);
    const Staircase& s = map.staircases()[0].stairs;
    ASSERT_EQ(s.steps.size(), 10u);
    for (int i = 0; i < 10; ++i) {
        EXPECT_NEAR(s.steps[i].centre().z(), truth.edgeCentre(i).z(), 1e-6) << "step " << i;
    }
}

}  // namespace
}  // namespace stairmap

namespace stairmap {
namespace {

TEST(LandmarkMap, BottomAndTopViewsWithoutCommonStepJoinWhenOneContinuesTheOther) {
    test::FlightTruth truth;
    truth.num_steps = 16;
    truth.heading_rad = 0.9;
    LandmarkMap map;
    std::mt19937 rng(32);
    test::ViewSpec bottom = noisy(0, 4);
    test::ViewSpec top = noisy(10, 15);
    top.descending = true;
    map.addDetection(test::makeDetection(truth, bottom, rng), 0.0);
    const LandmarkUpdate u = map.addDetection(test::makeDetection(truth, top, rng), 1.0);
    EXPECT_FALSE(u.created);
    ASSERT_EQ(map.staircases().size(), 1u);
    EXPECT_EQ(map.staircases()[0].stairs.steps.size(), 11u);
    EXPECT_NEAR(map.staircases()[0].stairs.step_height, truth.rise, 0.005);
}

TEST(LandmarkMap, FlightAfterALandingStaysSeparate) {
    // Straight run: flight A, a 1.2 m landing, flight B continuing in the same direction.
    test::FlightTruth a;
    a.num_steps = 8;
    test::FlightTruth b = a;
    b.floor_z = a.topZ();
    b.origin_xy = a.edgeCentre(a.num_steps - 1).head<2>() + (1.2 + a.run) * a.uphill();
    LandmarkMap map;
    std::mt19937 rng(33);
    for (int k = 0; k < 3; ++k) {
        map.addDetection(test::makeDetection(a, noisy(0, 7), rng), k);
        map.addDetection(test::makeDetection(b, noisy(0, 7), rng), k);
    }
    EXPECT_EQ(map.staircases().size(), 2u);
}

}  // namespace
}  // namespace stairmap
