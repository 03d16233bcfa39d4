// Flight measurements from canonical landmarks with known geometry.
#include "export/FlightGeometry.h"

#include <gtest/gtest.h>

#include <cmath>

#include "SyntheticLandmarks.h"

namespace stairmap::exporting {
namespace {

TEST(FlightGeometry, StraightFlight) {
    test::FlightSpec f;
    f.foot = {1.0, 2.0, 0.5};
    f.heading_rad = 0.7;
    f.risers = 12;
    const FlightGeometry g = measureFlight(test::makeLandmark(1, f, 0, 1));
    EXPECT_EQ(g.risers, 12);
    EXPECT_EQ(g.max_risers_between_landings, 12);
    EXPECT_TRUE(g.mid_landings.empty());
    EXPECT_NEAR(g.slope_deg, std::atan2(0.17, 0.28) * 180.0 / M_PI, 1e-9);
    EXPECT_LT((g.bottom - f.foot).norm(), 1e-9);
    const Eigen::Vector3d top = f.foot +
                                Eigen::Vector3d(std::cos(0.7), std::sin(0.7), 0) * 11 * 0.28 +
                                Eigen::Vector3d(0, 0, 12 * 0.17);
    EXPECT_LT((g.top - top).norm(), 1e-9);
    EXPECT_NEAR(g.length_m, 0.17 + 11 * std::hypot(0.17, 0.28), 1e-9);
    EXPECT_NEAR(g.rise_std_m, 0.0, 1e-9);
    EXPECT_NEAR(g.run_std_m, 0.0, 1e-9);
    EXPECT_NEAR(g.width_std_m, 0.0, 1e-9);
}

TEST(FlightGeometry, MidLandingSplitsTheRisers) {
    test::FlightSpec f;
    f.risers = 14;
    f.landing_after = 9;
    f.landing_length = 1.3;
    const FlightGeometry g = measureFlight(test::makeLandmark(1, f, 0, 1));
    ASSERT_EQ(g.mid_landings.size(), 1u);
    EXPECT_EQ(g.max_risers_between_landings, 9);
    EXPECT_NEAR(g.mid_landings[0].length_m, 1.3, 1e-9);
    EXPECT_NEAR(g.mid_landings[0].centre.z(), 9 * 0.17, 1e-9);  // level with nosing 8
    EXPECT_NEAR(g.mid_landings[0].centre.x(), 8 * 0.28 + 0.65, 1e-9);
    EXPECT_NEAR(g.run_std_m, 0.0, 1e-9);  // the landing is not a run
}

TEST(FlightGeometry, SpreadOfUnevenSteps) {
    test::FlightSpec f;
    f.risers = 5;
    StaircaseLandmark lm = test::makeLandmark(1, f, 0, 1);
    // Rises become 0.17 + {+0.01, -0.01, +0.01, -0.01}.
    for (int k : {1, 3}) {
        lm.stairs.steps[k].start.z() += 0.01;
        lm.stairs.steps[k].end.z() += 0.01;
    }
    lm.stairs.steps[4].end.y() += 0.2;  // one edge 0.2 m short (end is on the right, -y)
    const FlightGeometry g = measureFlight(lm);
    const double rise_std = std::sqrt(4 * 0.01 * 0.01 / 3.0);  // values 0.18 0.16 0.18 0.16
    EXPECT_NEAR(g.rise_std_m, rise_std, 1e-9);
    const double width_std = std::sqrt((4 * 0.04 * 0.04 + 0.16 * 0.16) / 4.0);  // 4 x 1.0, 1 x 0.8
    EXPECT_NEAR(g.width_std_m, width_std, 1e-6);
}

}  // namespace
}  // namespace stairmap::exporting
