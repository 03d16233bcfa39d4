// core/TurningFlight: a spiral's axis, step angle and run at mid radius from its edges, built from
// a known helix (truth from the construction); straight flights have none.
#include "core/TurningFlight.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace stairmap {
namespace {

constexpr double kDeg = M_PI / 180.0;

struct Spiral {
    Eigen::Vector2d axis{-2.0, 3.0};
    double inner = 0.15, outer = 1.25;  ///< [m] column and outer radius
    double step = 31.0 * kDeg;          ///< [rad] turn per step (signed: clockwise < 0)
    double rise = 0.18;
    double mid() const { return 0.5 * (inner + outer); }
    double run() const { return 2.0 * mid() * std::sin(0.5 * std::abs(step)); }
};

/// Nosing k: radial from `from` to `to` [m] around the axis at angle 40 deg + k step.
StairEdge nosing(const Spiral& s, int k, double from, double to) {
    const double a = 40.0 * kDeg + k * s.step;
    const Eigen::Vector2d u(std::cos(a), std::sin(a));
    StairEdge e;
    e.start << s.axis + from * u, k * s.rise;
    e.end << s.axis + to * u, k * s.rise;
    e.num_points = 20;
    return e;
}

TEST(TurningFlight, RunAtMidRadiusOfASpiralSeenPartly) {
    for (double step : {31.0 * kDeg, -24.0 * kDeg, 45.0 * kDeg}) {
        Spiral sp;
        sp.step = step;
        Staircase s;
        for (int k = 0; k < 8; ++k) {
            // Every third nosing seen only near the column (its outer part hidden), one put back.
            const double to = k % 3 == 2 ? 0.7 : sp.outer;
            s.steps.push_back(nosing(sp, k, sp.inner, to));
            if (k == 4) s.steps.back().num_points = 0;
        }
        const auto t = turningFlight(s);
        ASSERT_TRUE(t.has_value()) << step;
        EXPECT_LT((t->axis - sp.axis).norm(), 0.01);
        EXPECT_NEAR(t->step_angle_rad, std::abs(step), 0.2 * kDeg);
        EXPECT_NEAR(t->inner_radius_m, sp.inner, 0.01);
        EXPECT_NEAR(t->outer_radius_m, sp.outer, 0.01);
        EXPECT_NEAR(t->run_m, sp.run(), 0.005) << step;
    }
}

// A far view of a 4-step spiral (dev3 r0229): the column and the wedges below hide the inner part
// of two of the four nosings (seen from 0.47 and 0.66 m out on a 0.19 m column). The column's
// radius comes from the nosings that reach it; the median of the inner ends read the run 5 cm long.
TEST(TurningFlight, RunOfASpiralWhoseNosingsAreHiddenNearTheColumn) {
    Spiral sp;
    sp.inner = 0.19;
    sp.outer = 1.29;
    sp.step = 24.0 * kDeg;
    Staircase s;
    const double from[] = {0.66, 0.20, 0.21, 0.47};
    for (int k = 0; k < 4; ++k) s.steps.push_back(nosing(sp, k, from[k], sp.outer));
    const auto t = turningFlight(s);
    ASSERT_TRUE(t.has_value());
    EXPECT_NEAR(t->inner_radius_m, sp.inner, 0.025);  // the nearest seen from 1-2 cm off it
    EXPECT_NEAR(t->run_m, sp.run(), 0.01);
}

// One level's line off its nosing's angle (a back edge one step ahead, a short line at the
// column): the step angle is the median of the pairwise angle steps, which that level moves in 5
// of 15 pairs only. A least-squares slope over the levels read 22.1 deg for 20 here.
TEST(TurningFlight, OneLevelOffItsAngleDoesNotTurnTheStep) {
    for (double sign : {1.0, -1.0}) {
        Spiral sp;
        sp.step = sign * 20.0 * kDeg;
        Staircase s;
        for (int k = 0; k < 6; ++k) s.steps.push_back(nosing(sp, k, sp.inner, sp.outer));
        const Eigen::Rotation2Dd off(sign * 15.0 * kDeg);  // the top level turned on about the axis
        for (Eigen::Vector3d* end : {&s.steps.back().start, &s.steps.back().end})
            end->head<2>() = sp.axis + off * (end->head<2>() - sp.axis);
        const auto t = turningFlight(s);
        ASSERT_TRUE(t.has_value());
        EXPECT_NEAR(t->step_angle_rad, 20.0 * kDeg, 0.5 * kDeg) << sign;
        EXPECT_NEAR(t->run_m, sp.run(), 0.005) << sign;
    }
}

TEST(TurningFlight, RunAtMidRadiusIsTheChordBetweenNosingsThere) {
    TurningFlight t;
    t.step_angle_rad = 30.0 * kDeg;
    t.outer_radius_m = 1.1;
    // Two nosings 30 deg apart, both crossing the circle of radius (0.3 + 1.1) / 2 = 0.7 m: the
    // distance between their crossings.
    const Eigen::Vector2d a(0.7, 0.0), b(0.7 * std::cos(30.0 * kDeg), 0.7 * std::sin(30.0 * kDeg));
    EXPECT_NEAR(runAtMidRadius(t, 0.3), (b - a).norm(), 1e-9);
    EXPECT_NEAR(runAtMidRadius(t, 1.1), 2.0 * 1.1 * std::sin(15.0 * kDeg), 1e-9);
}

TEST(TurningFlight, StraightFlightsAndNoisyEdgesHaveNone) {
    Staircase straight;
    for (int k = 0; k < 6; ++k) {
        StairEdge e;
        const double skew = (k % 2 ? 4.0 : -4.0) * kDeg;  // edge directions scattered by +-4 deg
        e.start = {1.5 + 0.3 * k - 0.6 * std::sin(skew), 0.6 * std::cos(skew), 0.17 * k};
        e.end = {1.5 + 0.3 * k + 0.6 * std::sin(skew), -0.6 * std::cos(skew), 0.17 * k};
        e.num_points = 20;
        straight.steps.push_back(e);
    }
    EXPECT_FALSE(turningFlight(straight).has_value());
    Staircase two;
    two.steps.assign(straight.steps.begin(), straight.steps.begin() + 2);
    EXPECT_FALSE(turningFlight(two).has_value());
}

}  // namespace
}  // namespace stairmap
