// Verdicts at and across each limit of a profile, and the direction permissions.
#include "export/Traversability.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

namespace stairmap::exporting {
namespace {

RobotProfile profile() {
    RobotProfile p;
    p.max_rise_m = 0.18;
    p.min_run_m = 0.25;
    p.min_width_m = 0.80;
    p.max_slope_deg = 36.0;
    p.max_steps_without_landing = 12;
    return p;
}

/// A flight comfortably inside every limit of profile().
FlightGeometry easyFlight() {
    FlightGeometry f;
    f.rise_m = 0.15;
    f.run_m = 0.30;
    f.width_m = 1.2;
    f.slope_deg = 26.6;
    f.risers = f.max_risers_between_landings = 8;
    return f;
}

struct LimitCase {
    const char* name;
    std::function<void(FlightGeometry&, double)> set;  ///< puts the flight at limit + delta
    double limit;
    double across;       ///< the delta that breaks the limit (sign: the failing side)
    const char* reason;  ///< start of the expected reason
};

class AtAndAcrossLimit : public ::testing::TestWithParam<LimitCase> {};

TEST_P(AtAndAcrossLimit, PassesAtLimitFailsAcross) {
    const LimitCase& c = GetParam();
    for (Travel t : {Travel::Up, Travel::Down}) {
        FlightGeometry at = easyFlight();
        c.set(at, c.limit);
        const Verdict ok = judgeFlight(at, profile(), t);
        EXPECT_TRUE(ok.traversable)
            << c.name << " at the limit: " << ::testing::PrintToString(ok.reasons);

        FlightGeometry across = easyFlight();
        c.set(across, c.limit + c.across);
        const Verdict no = judgeFlight(across, profile(), t);
        EXPECT_FALSE(no.traversable) << c.name << " across the limit";
        ASSERT_EQ(no.reasons.size(), 1u) << ::testing::PrintToString(no.reasons);
        EXPECT_EQ(no.reasons[0].rfind(c.reason, 0), 0u) << no.reasons[0];
    }
}

INSTANTIATE_TEST_SUITE_P(
    EachLimit, AtAndAcrossLimit,
    ::testing::Values(LimitCase{"rise", [](FlightGeometry& f, double v) { f.rise_m = v; }, 0.18,
                                0.01, "rise 0.190 > 0.180 m"},
                      LimitCase{"run", [](FlightGeometry& f, double v) { f.run_m = v; }, 0.25,
                                -0.01, "run 0.240 < 0.250 m"},
                      LimitCase{"width", [](FlightGeometry& f, double v) { f.width_m = v; }, 0.80,
                                -0.05, "width 0.75 < 0.80 m"},
                      LimitCase{"slope", [](FlightGeometry& f, double v) { f.slope_deg = v; }, 36.0,
                                0.5, "slope 36.5 > 36.0 deg"},
                      LimitCase{"risers",
                                [](FlightGeometry& f, double v) {
                                    f.max_risers_between_landings = static_cast<int>(v);
                                },
                                12, 1, "13 risers without a landing > 12"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(Traversability, DirectionPermissions) {
    RobotProfile p = profile();
    p.can_ascend = false;
    EXPECT_FALSE(judgeFlight(easyFlight(), p, Travel::Up).traversable);
    EXPECT_TRUE(judgeFlight(easyFlight(), p, Travel::Down).traversable);
    p.can_ascend = true;
    p.can_descend = false;
    EXPECT_TRUE(judgeFlight(easyFlight(), p, Travel::Up).traversable);
    const Verdict down = judgeFlight(easyFlight(), p, Travel::Down);
    EXPECT_FALSE(down.traversable);
    EXPECT_EQ(down.reasons, std::vector<std::string>{"cannot go down stairs"});
}

TEST(Traversability, EveryFailedLimitIsListed) {
    FlightGeometry f = easyFlight();
    f.rise_m = 0.25;
    f.run_m = 0.20;
    f.width_m = 0.5;
    f.slope_deg = 51.3;
    f.max_risers_between_landings = 20;
    RobotProfile p = profile();
    p.can_ascend = false;
    const Verdict v = judgeFlight(f, p, Travel::Up);
    EXPECT_FALSE(v.traversable);
    EXPECT_EQ(v.reasons.size(), 6u) << ::testing::PrintToString(v.reasons);
}

TEST(Traversability, ProfileValidationNamesTheField) {
    RobotProfile p = profile();
    p.clearance_m = -0.1;
    try {
        validateRobotProfile(p);
        FAIL() << "a negative clearance was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("clearance_m"), std::string::npos) << e.what();
    }
    p = profile();
    p.max_slope_deg = 90.0;
    EXPECT_THROW(validateRobotProfile(p), std::invalid_argument);
    EXPECT_NO_THROW(validateRobotProfile(profile()));
}

}  // namespace
}  // namespace stairmap::exporting
