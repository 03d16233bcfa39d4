// Detector behaviour on whole scenes: negatives (things that are not staircases), several
// staircases in one cloud, floor handling, sparse and partial clouds, bad points.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/DetectionMatching.h"
#include "support/SyntheticScenes.h"
#include "core/StairDetector.h"
#include "core/StaircaseGeometry.h"

namespace stairmap::test {
namespace {

constexpr double kDeg = M_PI / 180.0;

DetectionResult detect(const SceneBuilder& scene, std::optional<double> floor_z = -0.5) {
    return StairDetector().detect(scene.cloud(), floor_z);
}

void expectGeometry(const Staircase& s, const StairTruth& t) {
    EXPECT_NEAR(s.step_height, t.rise_m, 0.01);
    EXPECT_NEAR(s.step_depth, t.run_m, 0.015);
    EXPECT_NEAR(s.step_width, t.width_m, 0.10);
}

TEST(StairDetectorNegatives, FlatFloorGivesNothing) {
    SceneBuilder scene({});
    scene.addFloor();
    const auto r = detect(scene);
    EXPECT_TRUE(r.staircases.empty()) << describe(r);
    EXPECT_NEAR(r.floor_z, -0.5, 0.01);
}

TEST(StairDetectorNegatives, FurnitureGivesNothing) {
    SceneBuilder scene({});
    scene.addFloor();
    scene.addTable({2.0, 0.5}, 0.3, 1.4, 0.8, 0.75);                // table
    scene.addBox({-1.5, 1.8}, 1.2, 1.0, 0.35, -0.5, 1.8);           // tall shelf
    scene.addBox({-1.0, -2.0}, 0.0, 0.5, 0.5, -0.5, 0.45);          // chair-sized box
    scene.addBox({1.2, -2.0}, 0.4, 2.0, 0.9, -0.5, 0.42);           // sofa-sized box ...
    scene.addBox({1.2, -2.0}, 0.4, 2.0, 0.2, -0.5 + 0.42, 0.35);    // ... with a backrest
    scene.addWall({-3.0, 3.0}, {3.0, 3.0}, 2.5);
    const auto r = detect(scene);
    EXPECT_TRUE(r.staircases.empty()) << describe(r);
}

class RampIsNotAStaircase : public testing::TestWithParam<double> {};

TEST_P(RampIsNotAStaircase, AnyModerateSlope) {
    SceneBuilder scene({});
    scene.addFloor();
    scene.addRamp(1.5, 20 * kDeg, GetParam() * kDeg, 3.0, 1.2);
    const auto r = detect(scene);
    EXPECT_TRUE(r.staircases.empty()) << "slope " << GetParam() << " deg: " << describe(r);
}

INSTANTIATE_TEST_SUITE_P(Slopes, RampIsNotAStaircase, testing::Values(5.0, 10.0, 15.0));

TEST(StairDetectorNegatives, SingleCurbGivesNothing) {
    SceneBuilder scene({});
    scene.addFloor();
    scene.addBox({2.0, 0.0}, 90 * kDeg, 3.0, 0.3, -0.5, 0.15);
    const auto r = detect(scene);
    EXPECT_TRUE(r.staircases.empty()) << describe(r);
}

class ShortStageIsNotAStaircase : public testing::TestWithParam<int> {};

TEST_P(ShortStageIsNotAStaircase, OneOrTwoSteps) {
    SceneBuilder scene({});
    scene.addFloor();
    // k steps up to a stage: k + 1 rises counting the platform's own edge.
    scene.addTiers(1.8, -30 * kDeg, GetParam() + 1, 0.18, 0.30, 2.0, 2.0);
    const auto r = detect(scene);
    EXPECT_TRUE(r.staircases.empty()) << GetParam() << " steps: " << describe(r);
}

INSTANTIATE_TEST_SUITE_P(Steps, ShortStageIsNotAStaircase, testing::Values(1, 2));

TEST(StairDetectorNegatives, BleachersWithTallTiersGiveNothing) {
    SceneBuilder scene({});
    scene.addFloor();
    scene.addTiers(1.5, 10 * kDeg, 5, 0.40, 0.60, 3.0, 1.0);
    const auto r = detect(scene);
    EXPECT_TRUE(r.staircases.empty()) << describe(r);
}

TEST(StairDetectorScenes, ShortFlightOfThreeStepsIsAccepted) {
    SceneBuilder scene({});
    StairSpec spec;
    spec.num_risers = 4;  // three steps and the landing: 4 nosings
    spec.yaw_rad = 40 * kDeg;
    const StairTruth t = scene.addStairs(spec);
    scene.addFloor();
    const auto r = detect(scene);
    ASSERT_EQ(r.staircases.size(), 1u) << describe(r);
    const Staircase* s = matchTruth(r, t);
    ASSERT_NE(s, nullptr) << describe(r);
    EXPECT_EQ(s->steps.size(), 4u);
}

TEST(StairDetectorScenes, AscendingAndDescendingInOneCloud) {
    SceneBuilder scene({});
    StairSpec up;
    up.distance_m = 1.8;
    up.yaw_rad = 10 * kDeg;
    StairSpec down;
    down.kind = StairKind::Descending;
    down.distance_m = 1.5;
    down.yaw_rad = 190 * kDeg;
    const StairTruth tu = scene.addStairs(up);
    const StairTruth td = scene.addStairs(down);
    scene.addFloor();
    const auto r = detect(scene);
    ASSERT_EQ(r.staircases.size(), 2u) << describe(r);
    const Staircase* su = matchTruth(r, tu);
    const Staircase* sd = matchTruth(r, td);
    ASSERT_NE(su, nullptr) << describe(r);
    ASSERT_NE(sd, nullptr) << describe(r);
    expectGeometry(*su, tu);
    expectGeometry(*sd, td);
}

TEST(StairDetectorScenes, TwoAscendingStaircasesInOneCloud) {
    SceneBuilder scene({});
    StairSpec a;
    a.yaw_rad = 45 * kDeg;
    StairSpec b;
    b.yaw_rad = -120 * kDeg;
    b.rise_m = 0.15;
    b.run_m = 0.29;
    b.width_m = 1.0;
    const StairTruth ta = scene.addStairs(a);
    const StairTruth tb = scene.addStairs(b);
    scene.addFloor();
    const auto r = detect(scene);
    ASSERT_EQ(r.staircases.size(), 2u) << describe(r);
    ASSERT_NE(matchTruth(r, ta), nullptr) << describe(r);
    ASSERT_NE(matchTruth(r, tb), nullptr) << describe(r);
    expectGeometry(*matchTruth(r, ta), ta);
    expectGeometry(*matchTruth(r, tb), tb);
}

TEST(StairDetectorFloor, EstimatedWhenNotGiven) {
    SceneOptions opt;
    opt.floor_z = -0.62;
    SceneBuilder scene(opt);
    const StairTruth t = scene.addStairs({});
    scene.addFloor();
    const auto r = detect(scene, std::nullopt);
    EXPECT_TRUE(r.floor_estimated);
    EXPECT_NEAR(r.floor_z, -0.62, 0.02);
    ASSERT_NE(matchTruth(r, t), nullptr) << describe(r);
}

class FloorOffset : public testing::TestWithParam<double> {};

TEST_P(FloorOffset, GivenFloorOffByCentimetresKeepsTheFirstStep) {
    SceneBuilder scene({});
    StairSpec spec;
    spec.rise_m = 0.13;  // a low first step is the one a wrong floor loses
    spec.run_m = 0.26;   // slope 26.6 deg, inside Definition 1
    const StairTruth t = scene.addStairs(spec);
    scene.addFloor();
    const auto r = detect(scene, -0.5 + GetParam());
    EXPECT_FALSE(r.floor_estimated);
    const Staircase* s = matchTruth(r, t);
    ASSERT_NE(s, nullptr) << describe(r);
    EXPECT_EQ(s->steps.size(), t.nosings.size());
}

INSTANTIATE_TEST_SUITE_P(Offsets, FloorOffset, testing::Values(-0.05, -0.03, 0.03, 0.05));

TEST(StairDetectorScenes, FarSparseStaircaseIsFound) {
    SceneOptions opt;
    opt.floor_half_size_m = 6.5;
    opt.sparse_from_m = 3.0;  // density falls with range squared, like an accumulated LiDAR cloud
    SceneBuilder scene(opt);
    StairSpec spec;
    spec.distance_m = 5.0;
    spec.yaw_rad = -20 * kDeg;
    const StairTruth t = scene.addStairs(spec);
    scene.addFloor();
    const auto r = detect(scene);
    const Staircase* s = matchTruth(r, t);
    ASSERT_NE(s, nullptr) << describe(r);
    EXPECT_NEAR(s->step_height, t.rise_m, 0.015);
    EXPECT_NEAR(s->step_depth, t.run_m, 0.03);
}

TEST(StairDetectorScenes, PartialViewOfADepthCamera) {
    SceneBuilder scene({});
    const StairTruth t = scene.addStairs({});
    scene.addFloor();
    PointCloud fov;  // 70 deg horizontal field of view, 4 m range, in front of the robot
    for (const auto& p : scene.cloud()) {
        if (p.x() > 0.3 && std::abs(std::atan2(p.y(), p.x())) < 35 * kDeg && p.norm() < 4.0)
            fov.push_back(p);
    }
    const auto r = StairDetector().detect(fov, -0.5);
    const Staircase* s = matchTruth(r, t);
    ASSERT_NE(s, nullptr) << describe(r);
    EXPECT_NEAR(s->step_height, t.rise_m, 0.01);
    EXPECT_NEAR(s->step_depth, t.run_m, 0.015);
}

TEST(StairDetectorScenes, AFlightRisingFromAPitIsFoundWholeWithItsStart) {
    // The robot stands on a platform (its floor, z = -0.5) ending 1 m before a flight that rises
    // from a pit two rises deeper: two nosings lie below the robot's floor, one at its level
    // (a ground line, never searched), four above. The whole flight is reported, starting on the
    // pit's floor: flightStartZ - floor = -2 rises (the detect output's start_z).
    SceneOptions opt;
    opt.floor_z = -0.84;  // the builder's floor: the pit, where the flight starts
    SceneBuilder scene(opt);
    StairSpec spec;
    spec.num_risers = 7;
    spec.rise_m = 0.17;
    spec.distance_m = 2.2;
    const StairTruth t = scene.addStairs(spec);
    scene.addFloor();
    scene.addBox({-1.25, 0.0}, 0.0, 4.5, 7.0, -0.84, 0.34);  // the robot's floor: x < 1 m
    const auto r = StairDetector().detect(scene.cloud(), -0.5);
    const Staircase* s = matchTruth(r, t);
    ASSERT_NE(s, nullptr) << describe(r);
    EXPECT_EQ(s->steps.size(), t.nosings.size()) << describe(r);
    EXPECT_NEAR(s->steps.front().centre().z(), t.nosings.front().first.z(), 0.02);
    EXPECT_NEAR(flightStartZ(*s) - (-0.5), -2 * spec.rise_m, 0.02);
    EXPECT_NEAR(s->step_height, spec.rise_m, 0.01);
}

TEST(StairDetectorInput, EmptyCloudGivesEmptyResult) {
    const auto r = StairDetector().detect({}, -0.5);
    EXPECT_TRUE(r.staircases.empty());
    const auto r2 = StairDetector().detect({}, std::nullopt);
    EXPECT_TRUE(r2.staircases.empty());
}

TEST(StairDetectorInput, NonFinitePointsAreIgnored) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    PointCloud bad(500, Eigen::Vector3f(nan, 0, 0));
    bad.resize(1000, Eigen::Vector3f(inf, -inf, inf));
    EXPECT_TRUE(StairDetector().detect(bad, -0.5).staircases.empty());
    EXPECT_TRUE(StairDetector().detect(bad, std::nullopt).staircases.empty());

    SceneBuilder scene({});
    const StairTruth t = scene.addStairs({});
    scene.addFloor();
    PointCloud mixed = scene.cloud();
    for (std::size_t i = 0; i < mixed.size(); i += 10) mixed[i] = (i % 20 == 0) ? bad[0] : bad[999];
    const auto r = StairDetector().detect(mixed, -0.5);
    ASSERT_EQ(r.staircases.size(), 1u) << describe(r);
    EXPECT_NE(matchTruth(r, t), nullptr) << describe(r);
}

}  // namespace
}  // namespace stairmap::test
