// The detector's optional debug record: same results with and without it, its contents, and the
// rule explanations agreeing with the rules themselves.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/SyntheticScenes.h"
#include "core/StairDetector.h"
#include "core/StairPairExplain.h"
#include "core/StairSearch.h"

namespace stairmap {
namespace {

using test::SceneBuilder;
using test::SceneOptions;
using test::StairSpec;

constexpr double kDeg = M_PI / 180.0;

/// A horizontal segment of `length` centred at (x, y, z), direction angle `alpha`.
LineSegment segment(double x, double y, double z, double alpha, double length) {
    LineSegment l;
    const Eigen::Vector2d u(std::cos(alpha), std::sin(alpha));
    l.start = Eigen::Vector2d(x, y) - 0.5 * length * u;
    l.end = Eigen::Vector2d(x, y) + 0.5 * length * u;
    l.z = z;
    l.theta = alpha + M_PI / 2;
    l.rho = std::cos(l.theta) * x + std::sin(l.theta) * y;
    if (l.rho < 0) {
        l.rho = -l.rho;
        l.theta -= M_PI;
    }
    l.num_points = 50;
    return l;
}

bool sameStaircases(const DetectionResult& a, const DetectionResult& b) {
    if (a.staircases.size() != b.staircases.size() || a.floor_z != b.floor_z) return false;
    for (std::size_t i = 0; i < a.staircases.size(); ++i) {
        const auto& s = a.staircases[i];
        const auto& t = b.staircases[i];
        if (s.steps.size() != t.steps.size() || s.step_height != t.step_height ||
            s.location != t.location)
            return false;
    }
    return true;
}

TEST(DetectorDebug, SameResultWithAndWithoutTheRecord) {
    SceneOptions opt;
    SceneBuilder scene(opt);
    StairSpec up;
    up.distance_m = 1.8;
    scene.addStairs(up);
    StairSpec down;
    down.kind = StairKind::Descending;
    down.yaw_rad = M_PI;
    scene.addStairs(down);
    scene.addFloor();
    const StairDetector detector;
    const DetectionResult plain = detector.detect(scene.cloud(), opt.floor_z);
    DetectorDebug debug;
    const DetectionResult with = detector.detect(scene.cloud(), opt.floor_z, &debug);
    ASSERT_EQ(plain.staircases.size(), 2u);
    EXPECT_TRUE(sameStaircases(plain, with));
    // The record holds what the detector worked on.
    EXPECT_FALSE(debug.candidates.empty());
    EXPECT_GE(debug.lines_ascending.size(), 6u);   // at least one line per nosing
    EXPECT_GE(debug.lines_descending.size(), 5u);
    ASSERT_EQ(debug.accepted.size(), plain.staircases.size());
    EXPECT_EQ(debug.accepted[0].steps.size(), plain.staircases[0].steps.size());
    EXPECT_NEAR(debug.floor_z, plain.floor_z, 1e-12);
    // Real z (the search mirrors descending lines): the lower nosings lie below the floor.
    int below = 0;
    for (const auto& l : debug.lines_descending) below += l.z < opt.floor_z - 0.1;
    EXPECT_GE(below, 4);
    // A second call clears the record first.
    detector.detect(PointCloud{}, opt.floor_z, &debug);
    EXPECT_TRUE(debug.candidates.empty());
    EXPECT_TRUE(debug.accepted.empty());
}

TEST(DetectorDebug, ShortFlightIsRejectedForItsLength) {
    SceneOptions opt;
    SceneBuilder scene(opt);
    StairSpec spec;
    spec.num_risers = 2;  // two nosings: below min_steps (4)
    scene.addStairs(spec);
    scene.addFloor();
    DetectorDebug debug;
    const DetectionResult r = StairDetector().detect(scene.cloud(), opt.floor_z, &debug);
    EXPECT_TRUE(r.staircases.empty());
    bool found = false;
    for (const auto& c : debug.rejected) found = found || c.reason == "2 steps < 4";
    EXPECT_TRUE(found) << "no chain refused as '2 steps < 4' among " << debug.rejected.size();
}

TEST(DetectorDebug, TooHighRiseIsRejectedWithItsRule) {
    SceneOptions opt;
    SceneBuilder scene(opt);
    StairSpec spec;
    spec.rise_m = 0.42;  // above max_step_height_m + tolerance (0.34 m)
    spec.run_m = 0.40;
    scene.addStairs(spec);
    scene.addFloor();
    DetectorDebug debug;
    const DetectionResult r = StairDetector().detect(scene.cloud(), opt.floor_z, &debug);
    EXPECT_TRUE(r.staircases.empty());
    bool found = false;
    for (const auto& c : debug.rejected) found = found || c.reason.rfind("rise 0.4", 0) == 0;
    EXPECT_TRUE(found);
}

TEST(StairPairExplain, NamesTheFailedRule) {
    const DetectorParams p;  // rise 0.11-0.30 (+-0.04), run 0.15-0.45, parallel 45 deg
    const LineSegment low = segment(1.0, 0.0, 0.0, M_PI / 2, 1.0);
    EXPECT_EQ(explainStairPair(low, segment(1.3, 0.0, 0.17, M_PI / 2, 1.0), p), "");
    EXPECT_EQ(explainStairPair(low, segment(1.3, 0.0, 0.40, M_PI / 2, 1.0), p), "rise 0.40 > 0.34 m");
    EXPECT_EQ(explainStairPair(low, segment(1.3, 0.0, 0.05, M_PI / 2, 1.0), p), "rise 0.05 < 0.07 m");
    EXPECT_EQ(explainStairPair(low, segment(1.3, 0.0, 0.17, M_PI / 2 + 50 * kDeg, 1.0), p),
              "not parallel: 50\u00b0 > 45\u00b0");
    EXPECT_EQ(explainStairPair(low, segment(1.6, 0.0, 0.17, M_PI / 2, 1.0), p), "run 0.60 > 0.45 m");
    EXPECT_EQ(explainStairPair(low, segment(1.3, 3.0, 0.17, M_PI / 2, 1.0), p).rfind("overlap", 0), 0u);
    EXPECT_EQ(tooFewSteps(2, 3), "2 steps < 3");
}

TEST(StairPairExplain, AgreesWithTheRuleOnRandomPairs) {
    const DetectorParams p;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> xy(-0.6, 0.6), z(0.0, 0.45), ang(-0.8, 0.8),
        len(0.2, 1.5);
    int accepted = 0;
    for (int i = 0; i < 5000; ++i) {
        const LineSegment a = segment(1.0, 0.0, 0.0, M_PI / 2, len(rng));
        const LineSegment b = segment(1.0 + xy(rng), xy(rng), z(rng), M_PI / 2 + ang(rng), len(rng));
        const bool ok = checkStairPair(a, b, p).has_value();
        accepted += ok;
        EXPECT_EQ(explainStairPair(a, b, p).empty(), ok) << "pair " << i;
    }
    EXPECT_GT(accepted, 50);  // both verdicts were exercised
    EXPECT_LT(accepted, 4950);
}

}  // namespace
}  // namespace stairmap
