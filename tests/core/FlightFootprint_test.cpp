// The ground a found flight covers (FlightFootprint.h), on hand-made flights whose extent the
// test knows: a straight flight of 4 edges along +x and a turning one.
#include "core/FlightFootprint.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stairmap {
namespace {

constexpr double kRun = 0.3, kRise = 0.17, kWidth = 1.2;  // [m]

/// Four nosings along +x from x = 2, each kWidth wide about y = 0.
Staircase straightFlight() {
    Staircase s;
    s.heading_rad = 0.0;
    s.step_depth = kRun;
    s.step_height = kRise;
    for (int k = 0; k < 4; ++k) {
        StairEdge e;
        const double x = 2.0 + k * kRun, z = (k + 1) * kRise;
        e.start = {x, kWidth / 2, z};
        e.end = {x, -kWidth / 2, z};
        s.steps.push_back(e);
    }
    return s;
}

TEST(FlightFootprint, CoversTheTreadsAndARunBeforeAndBeyond) {
    const Staircase s = straightFlight();
    EXPECT_TRUE(onFlightFootprint({2.15, 0.0}, s));                // on the first tread
    EXPECT_TRUE(onFlightFootprint({2.0 - 0.8 * kRun, 0.4}, s));    // in front, within a run
    EXPECT_TRUE(onFlightFootprint({2.9 + 0.8 * kRun, -0.4}, s));   // beyond the last edge
    EXPECT_TRUE(onFlightFootprint({2.5, kWidth / 2 + 0.25}, s));   // an unseen side's margin
    EXPECT_FALSE(onFlightFootprint({2.0 - 1.5 * kRun, 0.0}, s));   // the floor in front
    EXPECT_FALSE(onFlightFootprint({2.9 + 1.5 * kRun, 0.0}, s));   // the landing beyond
    EXPECT_FALSE(onFlightFootprint({2.5, kWidth / 2 + 0.45}, s));  // a flight beside it
    EXPECT_FALSE(onFlightFootprint({2.5, 0.0}, Staircase{}));      // no steps, no ground
}

TEST(FlightFootprint, CoversTheEdgesOfATurningFlightWhoseHeadingBoxMissesThem) {
    // Three radial nosings about the origin turning 60 deg each: the heading from the first
    // edge's centre to the last's says little; the edges' own radius covers them.
    Staircase s;
    s.step_depth = kRun;
    for (int k = 0; k < 3; ++k) {
        const double a = k * M_PI / 3;
        StairEdge e;
        e.start = {0.2 * std::cos(a), 0.2 * std::sin(a), k * kRise};
        e.end = {1.0 * std::cos(a), 1.0 * std::sin(a), k * kRise};
        s.steps.push_back(e);
    }
    const Eigen::Vector3d c = 0.5 * (s.steps.back().start + s.steps.back().end);
    s.heading_rad = std::atan2(c.y() - 0.3, c.x() - 0.6);
    const double a = 2 * M_PI / 3 + 0.1;  // just past the last edge
    EXPECT_TRUE(onFlightFootprint({0.8 * std::cos(a), 0.8 * std::sin(a)}, s));
    EXPECT_FALSE(onFlightFootprint({-1.5, -1.0}, s));
}

TEST(FlightFootprint, AFlightOverlapsAnotherWhenOneOfItsEdgesLiesOnIt) {
    const Staircase found = straightFlight();
    Staircase upper = straightFlight();  // the same flight's upper part read again
    for (StairEdge& e : upper.steps) {
        e.start.x() += 2 * kRun;
        e.end.x() += 2 * kRun;
    }
    EXPECT_TRUE(overlapsAnyFlight(upper, {found}));
    Staircase beside = straightFlight();  // a second flight 2 m to the left
    for (StairEdge& e : beside.steps) {
        e.start.y() += 2.0;
        e.end.y() += 2.0;
    }
    EXPECT_FALSE(overlapsAnyFlight(beside, {found}));
    EXPECT_FALSE(overlapsAnyFlight(beside, {}));
}

/// `s` moved by (dx, dy, dz) [m].
Staircase moved(Staircase s, double dx, double dy, double dz) {
    for (StairEdge& e : s.steps) {
        e.start += Eigen::Vector3d(dx, dy, dz);
        e.end += Eigen::Vector3d(dx, dy, dz);
    }
    return s;
}

TEST(SecondViews, AShorterChainOverTheSameGroundAtOtherLevelsIsDropped) {
    // A second chain through the same flight, its levels 4 cm off and one step fewer, shifted a
    // little sideways: the longer chain stays, whichever comes first.
    Staircase second = moved(straightFlight(), 0.05, 0.2, 0.04);
    second.steps.pop_back();
    std::vector<Staircase> flights{second, straightFlight()};
    EXPECT_EQ(dropSecondViews(flights), 1);
    ASSERT_EQ(flights.size(), 1u);
    EXPECT_EQ(flights.front().steps.size(), 4u);
}

TEST(SecondViews, FlightsBesideBeyondOrTheOtherWayAreKept) {
    std::vector<Staircase> flights{straightFlight(),
                                   moved(straightFlight(), 0.0, kWidth + 0.5, 0.0),     // beside
                                   moved(straightFlight(), 4 * kRun + 0.5, 0.0, 1.0)};  // beyond
    Staircase down = straightFlight();  // the same ground the other way (a descent, or a
    down.heading_rad = M_PI;            // switchback's flight above)
    flights.push_back(moved(down, 0.0, 0.0, 1.5));
    Staircase descending = straightFlight();
    descending.direction = StairDirection::Descending;
    flights.push_back(descending);
    EXPECT_EQ(dropSecondViews(flights), 0);
    EXPECT_EQ(flights.size(), 5u);
}

}  // namespace
}  // namespace stairmap
