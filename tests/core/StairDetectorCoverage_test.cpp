// Issue 10: flights the randomised benchmark showed missed or cut short, each rebuilt from sim
// solids with known truth: narrow spirals turning more than 25 deg per step, shallow flights below
// the paper's 25 deg slope (down to 20), and flights with one nosing unseen (reported whole, not from the gap on).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/DetectionMatching.h"
#include "support/SyntheticScenes.h"
#include "core/StairDetector.h"

namespace stairmap::test {
namespace {

constexpr double kDeg = M_PI / 180.0;

/// Median over a staircase's edges of the 3D distance from the edge centre to the nearest true
/// nosing segment [m] (the evaluation's rule, core/Evaluation.h, in one number).
double medianNosingDistance(const Staircase& s, const StairTruth& t) {
    std::vector<double> d;
    for (const auto& e : s.steps) {
        double best = 1e9;
        for (const auto& [a, b] : t.nosings) {
            const Eigen::Vector3d ab = b - a;
            const double u = std::clamp((e.centre() - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
            best = std::min(best, (e.centre() - a - u * ab).norm());
        }
        d.push_back(best);
    }
    std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
    return d[d.size() / 2];
}

/// Staircases of the result whose edges lie on the truth's nosings (median distance < 8 cm).
int countOnTruth(const DetectionResult& r, const StairTruth& t) {
    int n = 0;
    for (const auto& s : r.staircases) n += medianNosingDistance(s, t) < 0.08 ? 1 : 0;
    return n;
}

class NarrowSpiral : public testing::TestWithParam<double> {};

// A spiral's treads turn run / mid radius per step: 0.28 m at a 0.54 m mid radius is 30 deg
// (the paper's 10 deg and the former 25 deg refused every pair).
TEST_P(NarrowSpiral, IsFoundAsOneFlight) {
    SceneBuilder scene({});
    scene.addFloor();
    StairSpec spec;
    spec.kind = StairKind::Spiral;
    spec.num_risers = 8;
    spec.rise_m = 0.18;
    spec.run_m = 0.28;
    spec.width_m = 0.7;
    spec.distance_m = 1.5;
    spec.turn_per_step_rad = GetParam() * kDeg;
    const StairTruth t = scene.addStairs(spec);
    const DetectionResult r = StairDetector().detect(scene.cloud(), -0.5);
    ASSERT_EQ(countOnTruth(r, t), 1) << describe(r);
    const Staircase* s = matchTruth(r, t);
    ASSERT_NE(s, nullptr) << describe(r);
    EXPECT_GE(s->steps.size(), 5u) << describe(r);
    EXPECT_NEAR(s->step_height, t.rise_m, 0.01);
}

INSTANTIATE_TEST_SUITE_P(TurnPerStepDeg, NarrowSpiral, testing::Values(30.0));

class ShallowFlight : public testing::TestWithParam<double> {};

// Entrance flights: 0.11 m rises on 0.34-0.38 m runs (16-18 deg; condition 3 allows the rise the
// sparse-cloud tolerance of 4 cm more, 22-24 deg, still under the paper's 25).
TEST_P(ShallowFlight, IsFoundWithItsGeometry) {
    SceneBuilder scene({});
    scene.addFloor();
    StairSpec spec;
    spec.num_risers = 5;
    spec.rise_m = 0.11;
    spec.run_m = GetParam();
    spec.distance_m = 1.5;
    spec.yaw_rad = 20 * kDeg;
    const StairTruth t = scene.addStairs(spec);
    const DetectionResult r = StairDetector().detect(scene.cloud(), -0.5);
    const Staircase* s = matchTruth(r, t);
    ASSERT_NE(s, nullptr) << "run " << GetParam() << ": " << describe(r);
    EXPECT_EQ(s->steps.size(), t.nosings.size()) << describe(r);
    EXPECT_NEAR(s->step_height, t.rise_m, 0.01);
    EXPECT_NEAR(s->step_depth, t.run_m, 0.015);
}

INSTANTIATE_TEST_SUITE_P(RunM, ShallowFlight, testing::Values(0.34, 0.38));

/// The cloud without the points within `radius` (XY) of the segment a-b: that nosing is unseen.
PointCloud withoutNosing(const PointCloud& cloud, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         double radius) {
    PointCloud out;
    const Eigen::Vector2d p0 = a.head<2>(), d = (b - a).head<2>();
    for (const auto& p : cloud) {
        const Eigen::Vector2d q = p.head<2>().cast<double>();
        const double s = std::clamp((q - p0).dot(d) / d.squaredNorm(), 0.0, 1.0);
        if ((q - p0 - s * d).norm() > radius) out.push_back(p);
    }
    return out;
}

class UnseenNosing : public testing::TestWithParam<int> {};

// One nosing gives no line (no points near it): the flight is still one flight of every step,
// starting at its first nosing, with the right rise.
TEST_P(UnseenNosing, FlightIsReportedWhole) {
    SceneBuilder scene({});
    scene.addFloor();
    StairSpec spec;
    spec.num_risers = 8;
    spec.distance_m = 1.5;
    spec.yaw_rad = -15 * kDeg;
    const StairTruth t = scene.addStairs(spec);
    const auto& gap = t.nosings[static_cast<std::size_t>(GetParam())];
    const PointCloud cloud = withoutNosing(scene.cloud(), gap.first, gap.second, 0.12);
    const DetectionResult r = StairDetector().detect(cloud, -0.5);
    ASSERT_EQ(countOnTruth(r, t), 1) << describe(r);
    const Staircase* s = matchTruth(r, t);
    ASSERT_NE(s, nullptr) << describe(r);
    EXPECT_EQ(s->steps.size(), t.nosings.size()) << describe(r);
    EXPECT_NEAR(s->step_height, t.rise_m, 0.01);
    EXPECT_NEAR(s->step_depth, t.run_m, 0.015);
}

INSTANTIATE_TEST_SUITE_P(NosingIndex, UnseenNosing, testing::Values(2, 4));

}  // namespace
}  // namespace stairmap::test
