// Straight flights read from their profile (findProfileChains), from hand-made nosing pieces of
// a known flight: pieces at their own places along each nosing, every other nosing missing.
#include "core/ProfileChains.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/HandMadeNosing.h"

namespace stairmap {
namespace {

constexpr double kFloorZ = -0.5;  // [m]
constexpr double kRise = 0.15;    // [m]
constexpr double kRun = 0.30;     // [m]
constexpr double kFirstX = 4.0;   // [m] the first nosing's distance (one rise above the floor)

/// Nosing k (1 = the lowest) of the flight: its distance up the flight and height.
double nosingX(int k) { return kFirstX + (k - 1) * kRun; }
double nosingZ(int k) { return kFloorZ + k * kRise; }

/// A 0.3 m piece of nosing k centred at lateral position y (20 points).
LineSegment piece(int k, double y, double dz = 0.0) {
    LineSegment l = test::nosingAcrossY(nosingX(k), nosingZ(k) + dz, 0.15);
    l.start.y() += y;
    l.end.y() += y;
    return l;
}

ProfileChainParams params() {
    ProfileChainParams p;
    p.floor_z = kFloorZ;
    return p;
}

TEST(ProfileChains, PiecesThatNeverOverlapAreOneFlightWithEveryStep) {
    // A far ring-aliased view: nosings 1-4 seen, then every other one up to 10, each piece at its
    // own place across a 2 m wide flight (no two consecutive pieces overlap laterally).
    std::vector<LineSegment> lines;
    const std::vector<int> seen = {1, 2, 3, 4, 6, 8, 10};
    for (std::size_t i = 0; i < seen.size(); ++i)
        lines.push_back(piece(seen[i], (i % 3 == 0 ? -0.8 : i % 3 == 1 ? 0.0 : 0.8)));
    const auto chains = findProfileChains(lines, params());
    ASSERT_EQ(chains.size(), 1u);
    const std::vector<LineSegment>& chain = chains.front();
    ASSERT_EQ(chain.size(), 10u);  // nosings 1-10, the skipped ones put back
    for (int k = 1; k <= 10; ++k) {
        const LineSegment& e = chain[k - 1];
        EXPECT_NEAR(e.z, nosingZ(k), 0.005) << "nosing " << k;
        EXPECT_NEAR(e.centre().x(), nosingX(k), 0.01) << "nosing " << k;
        const bool put_back = k == 5 || k == 7 || k == 9;
        EXPECT_EQ(e.num_points == 0, put_back) << "nosing " << k;
    }
}

TEST(ProfileChains, StepsBelowTheFirstSeenNosingArePutBackToTheFloor) {
    std::vector<LineSegment> lines;
    for (int k = 3; k <= 7; ++k) lines.push_back(piece(k, k % 2 ? 0.5 : -0.5));
    const auto chains = findProfileChains(lines, params());
    ASSERT_EQ(chains.size(), 1u);
    ASSERT_EQ(chains.front().size(), 7u);
    EXPECT_EQ(chains.front()[0].num_points, 0);
    EXPECT_NEAR(chains.front()[0].z, nosingZ(1), 0.005);
    EXPECT_NEAR(chains.front()[0].centre().x(), nosingX(1), 0.01);
}

TEST(ProfileChains, RiserHitsReadLowStillFallOnTheComb) {
    // Far rings read a riser up to a few cm under its nosing: the comb keeps them.
    std::vector<LineSegment> lines;
    const double low[] = {0.0, -0.03, -0.01, -0.04, 0.0, -0.02};
    for (int k = 1; k <= 6; ++k) lines.push_back(piece(k, k % 2 ? 0.6 : -0.6, low[k - 1]));
    const auto chains = findProfileChains(lines, params());
    ASSERT_EQ(chains.size(), 1u);
    EXPECT_EQ(chains.front().size(), 6u);
}

TEST(ProfileChains, FourSeenStepsAreTooFew) {
    std::vector<LineSegment> lines;
    for (int k = 1; k <= 4; ++k) lines.push_back(piece(k, 0.0));
    EXPECT_TRUE(findProfileChains(lines, params()).empty());
}

TEST(ProfileChains, AFirstNosingHalfARiseOffTheFloorsLevelsIsNoFlight) {
    // Evenly spaced parallel lines whose levels do not stand on the floor (a shelf's edges, a
    // ramp's rings): the first lies 1.5 rises above it.
    std::vector<LineSegment> lines;
    for (int k = 1; k <= 6; ++k) lines.push_back(piece(k, 0.0, 0.5 * kRise));
    EXPECT_TRUE(findProfileChains(lines, params()).empty());
}

TEST(ProfileChains, TwoUnseenStepsInARowEndTheComb) {
    // Nosings 1-3 and 6-8: neither part holds five seen steps.
    std::vector<LineSegment> lines;
    for (int k : {1, 2, 3, 6, 7, 8}) lines.push_back(piece(k, 0.0));
    EXPECT_TRUE(findProfileChains(lines, params()).empty());
}

TEST(ProfileChains, LinesThatTurnAreNoStraightFlight) {
    // Each piece turned 25 deg more than the one before (a spiral's radial lines).
    std::vector<LineSegment> lines;
    for (int k = 1; k <= 6; ++k) {
        LineSegment l = piece(k, 0.0);
        const double a = 25.0 * k * M_PI / 180.0;
        const Eigen::Vector2d c = l.centre(), d(-std::sin(a), std::cos(a));
        l.start = c - 0.15 * d;
        l.end = c + 0.15 * d;
        l.theta = a;
        l.rho = std::abs(c.dot(Eigen::Vector2d(std::cos(a), std::sin(a))));
        lines.push_back(l);
    }
    EXPECT_TRUE(findProfileChains(lines, params()).empty());
}

TEST(ProfileChains, PiecesWiderApartThanAFlightAreNotOneFlight) {
    std::vector<LineSegment> lines;
    for (int k = 1; k <= 6; ++k) lines.push_back(piece(k, k % 2 ? 1.6 : -1.6));  // 3.5 m apart
    EXPECT_TRUE(findProfileChains(lines, params()).empty());
}

}  // namespace
}  // namespace stairmap
