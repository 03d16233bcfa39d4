// Spot's staircase convention: origin at the bottom centre of the first riser, X up the stairs.
#include "export/SpotStaircase.h"

#include <gtest/gtest.h>

#include <cmath>

#include "SyntheticLandmarks.h"

namespace stairmap::exporting {
namespace {

TEST(SpotStaircase, FrameStepsAndLandings) {
    test::FlightSpec f;
    f.foot = {1.0, 2.0, 0.5};
    f.heading_rad = M_PI / 2;  // up the stairs = world +y
    f.risers = 8;
    const auto spot = toSpotStaircases(test::makeLandmark(4, f, 0, 1));
    ASSERT_EQ(spot.size(), 1u);
    const SpotStaircase& s = spot[0];
    EXPECT_EQ(s.id, "stairmap-4-0");
    EXPECT_LT((s.origin_world - f.foot).norm(), 1e-9);
    EXPECT_NEAR(s.yaw_rad, M_PI / 2, 1e-12);
    EXPECT_NEAR(s.average_rise_m, 0.17, 1e-12);
    ASSERT_EQ(s.steps.size(), 8u);
    for (int k = 0; k < 8; ++k) {
        const SpotStep& st = s.steps[k];
        EXPECT_NEAR(st.point.x(), k * 0.28, 1e-9) << k;
        EXPECT_NEAR(st.point.y(), 0.0, 1e-9) << k;
        EXPECT_NEAR(st.point.z(), (k + 1) * 0.17, 1e-9) << k;
        EXPECT_NEAR(st.north.x(), 1.0, 1e-9) << k;
        EXPECT_NEAR(st.width_m, 1.0, 1e-9) << k;
    }
    const SpotParams p;
    EXPECT_NEAR(s.bottom_landing.centre.x(), -0.5 * p.landing_length_m, 1e-9);
    EXPECT_NEAR(s.bottom_landing.centre.z(), 0.0, 1e-9);
    EXPECT_NEAR(s.bottom_landing.extent_y_m, 0.5, 1e-9);
    EXPECT_NEAR(s.top_landing.centre.x(), 7 * 0.28 + 0.5 * p.landing_length_m, 1e-9);
    EXPECT_NEAR(s.top_landing.centre.z(), 8 * 0.17, 1e-9);
}

TEST(SpotStaircase, MidLandingSplitsIntoTwoStaircases) {
    test::FlightSpec f;
    f.risers = 12;
    f.landing_after = 7;
    f.landing_length = 1.4;
    const auto spot = toSpotStaircases(test::makeLandmark(2, f, 0, 1));
    ASSERT_EQ(spot.size(), 2u);
    EXPECT_EQ(spot[0].steps.size(), 7u);
    EXPECT_EQ(spot[1].steps.size(), 5u);
    // The second starts at the foot of riser 8: below nosing 7 at x = 6 * 0.28 + 1.4.
    const Eigen::Vector3d foot2(6 * 0.28 + 1.4, 0.0, 7 * 0.17);
    EXPECT_LT((spot[1].origin_world - foot2).norm(), 1e-9);
    EXPECT_NEAR(spot[1].steps[0].point.z(), 0.17, 1e-9);
    // The landing is the top of the first and the bottom of the second, 1.4 m deep.
    EXPECT_NEAR(spot[0].top_landing.extent_x_m, 0.7, 1e-9);
    EXPECT_NEAR(spot[0].top_landing.centre.x(), 6 * 0.28 + 0.7, 1e-9);
    EXPECT_NEAR(spot[1].bottom_landing.extent_x_m, 0.7, 1e-9);
    EXPECT_NEAR(spot[1].bottom_landing.centre.x(), -0.7, 1e-9);
}

TEST(SpotStaircase, EmptyLandmarkGivesNothing) {
    EXPECT_TRUE(toSpotStaircases(StaircaseLandmark{}).empty());
}

}  // namespace
}  // namespace stairmap::exporting
