// End-to-end detector tests on synthetic scenes with known geometry (SyntheticScenes).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "support/DetectionMatching.h"
#include "support/SyntheticScenes.h"
#include "core/StairDetector.h"

namespace stairmap::test {
namespace {

constexpr double kDeg = M_PI / 180.0;

struct KindCase {
    StairKind kind;
    double yaw_deg;
    double distance_m;
};

std::string caseName(const testing::TestParamInfo<KindCase>& info) {
    std::ostringstream s;
    s << toString(info.param.kind) << "_yaw" << (info.param.yaw_deg < 0 ? "m" : "")
      << std::abs(static_cast<int>(info.param.yaw_deg)) << "_d"
      << static_cast<int>(info.param.distance_m * 10);
    return s.str();
}

class DetectsEveryKind : public testing::TestWithParam<KindCase> {};

TEST_P(DetectsEveryKind, FindsItWithAccurateGeometryAndNothingElse) {
    const KindCase c = GetParam();
    SceneOptions opt;
    opt.seed = 7 + static_cast<unsigned>(c.yaw_deg + 360);
    SceneBuilder scene(opt);
    StairSpec spec;
    spec.kind = c.kind;
    spec.yaw_rad = c.yaw_deg * kDeg;
    spec.distance_m = c.distance_m;
    spec.turn_per_step_rad = 0.08;
    const StairTruth truth = scene.addStairs(spec);
    scene.addFloor();

    const DetectionResult result = StairDetector().detect(scene.cloud(), opt.floor_z);
    SCOPED_TRACE(describe(result));
    ASSERT_EQ(result.staircases.size(), 1u) << "exactly the one staircase, no false positive";
    const Staircase* s = matchTruth(result, truth);
    ASSERT_NE(s, nullptr) << "detection does not start at the true first nosing";
    EXPECT_EQ(s->steps.size(), truth.nosings.size());
    EXPECT_NEAR(s->step_height, truth.rise_m, 0.01);
    EXPECT_NEAR(s->step_depth, truth.run_m, 0.015);
    EXPECT_NEAR(s->step_width, truth.width_m, 0.10);
    EXPECT_LT(headingError(*s, truth), 5 * kDeg);
    EXPECT_LT(nosingError(*s, truth), 0.05) << "every reported nosing lies on a true nosing";
}

std::vector<KindCase> allKindCases() {
    std::vector<KindCase> cases;
    for (StairKind k : {StairKind::Ascending, StairKind::Hollow, StairKind::Spiral,
                        StairKind::Descending, StairKind::Debris}) {
        for (double yaw : {0.0, 60.0, -100.0, 180.0}) cases.push_back({k, yaw, 2.0});
    }
    cases.push_back({StairKind::Ascending, 30.0, 0.6});
    cases.push_back({StairKind::Descending, -30.0, 1.0});
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Kinds, DetectsEveryKind, testing::ValuesIn(allKindCases()), caseName);

}  // namespace
}  // namespace stairmap::test
