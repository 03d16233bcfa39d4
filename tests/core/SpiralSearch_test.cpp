// core/SpiralSearch: spirals found by their axis, on wedge nosings built from a known helix
// (axis, radii, rise, step angle). Truth comes from the construction, never from the detector.

#include <gtest/gtest.h>

#include <cmath>

#include "core/SpiralSearch.h"

namespace stairmap {
namespace {

constexpr double kDeg = M_PI / 180.0;

/// A known spiral: nosing k (k = 1..levels) at height floor + k rise, angle phi0 + (k-1) step.
struct Helix {
    Eigen::Vector2d axis{3.0, 1.0};
    double inner = 0.12, outer = 0.9;  ///< [m] column and outer radius
    double floor_z = -0.5, rise = 0.18;
    double phi0 = 200.0 * kDeg, step = 50.0 * kDeg;  ///< > Algorithm 1's 45 deg parallel limit
    double angleOf(int k) const { return phi0 + (k - 1) * step; }
    double zOf(int k) const { return floor_z + k * rise; }
};

LineSegment radialLine(const Helix& h, double phi, double z) {
    const Eigen::Vector2d u(std::cos(phi), std::sin(phi));
    LineSegment l;
    l.start = h.axis + (h.inner + 0.02) * u;  // seen from just off the column
    l.end = h.axis + (h.outer - 0.02) * u;
    l.z = z;
    Eigen::Vector2d n(u.y(), -u.x());
    if (n.dot(l.start) < 0) n = -n;
    l.rho = n.dot(l.start);
    l.theta = std::atan2(n.y(), n.x());
    l.cov = Eigen::Matrix2d::Identity() * 1e-4;
    l.num_points = 30;
    return l;
}

/// A radial line seen only from `near` outward (the column hides its inner part), its line passing
/// `offset` [m] beside the axis.
LineSegment outerPartOf(const Helix& h, double phi, double z, double near, double offset = 0.0) {
    const Eigen::Vector2d u(std::cos(phi), std::sin(phi));
    const Eigen::Vector2d side(-u.y(), u.x());
    LineSegment l = radialLine(h, phi, z);
    l.start = h.axis + near * u + offset * side;
    l.end = h.axis + (h.outer - 0.02) * u + offset * side;
    Eigen::Vector2d n = side;
    if (n.dot(l.start) < 0) n = -n;
    l.rho = n.dot(l.start);
    l.theta = std::atan2(n.y(), n.x());
    return l;
}

/// Angle between the edge's direction (from its end nearer the axis) and nosing k's.
double angleError(const LineSegment& e, const Helix& h, int k) {
    const bool start_near = (e.start - h.axis).norm() < (e.end - h.axis).norm();
    const Eigen::Vector2d d = start_near ? e.end - e.start : e.start - e.end;
    return std::abs(std::remainder(std::atan2(d.y(), d.x()) - h.angleOf(k), 2.0 * M_PI));
}

/// A close view by a level LiDAR (dev2 r0228): the column hides the inner part of the lower
/// nosings (k = 1, 2 seen from 0.6 m out, past max_column_radius_m), and level 3 shows only its
/// back edge, from 0.52 m out and 0.1 m beside the axis (past max_axis_offset_m).
std::vector<LineSegment> closeViewLines(const Helix& h, int full_levels) {
    std::vector<LineSegment> lines;
    for (int k = 1; k <= 2; ++k) lines.push_back(outerPartOf(h, h.angleOf(k), h.zOf(k), 0.6));
    lines.push_back(outerPartOf(h, h.angleOf(4), h.zOf(3), 0.52, 0.1));
    for (int k = 7 - full_levels; k <= 6; ++k) lines.push_back(radialLine(h, h.angleOf(k), h.zOf(k)));
    return lines;
}

Helix closeViewHelix() {
    Helix h;
    h.inner = 0.19;
    h.outer = 0.83;
    h.rise = 0.17;
    h.step = 42.0 * kDeg;
    return h;
}

/// XY distance of the edge's centre from nosing k's centre.
double centreError(const LineSegment& e, const Helix& h, int k) {
    const Eigen::Vector2d u(std::cos(h.angleOf(k)), std::sin(h.angleOf(k)));
    return (e.centre() - (h.axis + 0.5 * (h.inner + h.outer) * u)).norm();
}

/// Spiral `f` has `levels` edges, edge k (1-based) at nosing k's height and place, put back
/// (no points) exactly where `put_back(k)`.
template <typename PutBack>
void expectLevelsOnTheHelix(const SpiralFlight& f, const Helix& h, int levels, PutBack put_back) {
    ASSERT_EQ(f.edges.size(), static_cast<std::size_t>(levels));
    for (int k = 1; k <= levels; ++k) {
        EXPECT_NEAR(f.edges[k - 1].z, h.zOf(k), 0.005) << k;
        EXPECT_LT(centreError(f.edges[k - 1], h, k), 0.03) << k;
        EXPECT_EQ(f.edges[k - 1].num_points == 0, put_back(k)) << k;
    }
}

SpiralSearchParams paramsFor(const Helix& h) {
    SpiralSearchParams p;
    p.floor_z = h.floor_z;
    return p;
}

TEST(SpiralSearch, FindsEveryNosingOfAStronglyTurningSpiral) {
    const Helix h;
    std::vector<LineSegment> front, back;
    for (int k = 1; k <= 7; ++k) (k % 2 ? front : back).push_back(radialLine(h, h.angleOf(k), h.zOf(k)));
    front.push_back(radialLine(h, 20.0 * kDeg, h.zOf(2)));  // a stray line at a nosing's height
    const auto spirals = findSpirals(front, back, paramsFor(h));
    ASSERT_EQ(spirals.size(), 1u);
    const SpiralFlight& f = spirals[0];
    ASSERT_EQ(f.edges.size(), 7u);
    EXPECT_LT((f.axis - h.axis).norm(), 0.01);
    EXPECT_NEAR(f.step_angle_rad, h.step, 1.0 * kDeg);
    // Run at mid radius: the chord between consecutive nosings' centres.
    EXPECT_NEAR(f.run_m, (h.inner + h.outer) * std::sin(0.5 * h.step), 0.03);
    for (int k = 1; k <= 7; ++k) {
        EXPECT_NEAR(f.edges[k - 1].z, h.zOf(k), 1e-9) << k;
        EXPECT_LT(centreError(f.edges[k - 1], h, k), 0.03) << k;
    }
}

TEST(SpiralSearch, PutsBackUnseenLevelsOnTheHelix) {
    Helix h;
    h.step = 25.0 * kDeg;
    h.phi0 = -60.0 * kDeg;
    std::vector<LineSegment> front;
    for (int k : {1, 3, 5, 7, 8}) front.push_back(radialLine(h, h.angleOf(k), h.zOf(k)));
    const auto spirals = findSpirals(front, {}, paramsFor(h));
    ASSERT_EQ(spirals.size(), 1u);
    EXPECT_EQ(spirals[0].seen_levels, 5);
    expectLevelsOnTheHelix(spirals[0], h, 8, [](int k) { return k == 2 || k == 4 || k == 6; });
}

// Four seen levels are one short of a spiral; asked for (few_seen_levels), the helix is reported
// apart with its four nosings, and only among the lines no spiral took.
TEST(SpiralSearch, ReportsAHelixOfFourSeenLevelsApartWhenAskedFor) {
    Helix h;
    std::vector<LineSegment> front;
    for (int k = 1; k <= 4; ++k) front.push_back(radialLine(h, h.angleOf(k), h.zOf(k)));
    SpiralSearchParams p = paramsFor(h);
    std::vector<SpiralFlight> few;
    EXPECT_TRUE(findSpirals(front, {}, p, &few).empty());
    EXPECT_TRUE(few.empty());  // not asked
    p.few_seen_levels = 4;
    EXPECT_TRUE(findSpirals(front, {}, p, &few).empty());
    ASSERT_EQ(few.size(), 1u);
    ASSERT_EQ(few[0].edges.size(), 4u);
    EXPECT_EQ(few[0].seen_levels, 4);
    EXPECT_LT((few[0].axis - h.axis).norm(), 0.01);
    for (int k = 1; k <= 4; ++k) {
        EXPECT_NEAR(few[0].edges[k - 1].z, h.zOf(k), 1e-9) << k;
        EXPECT_LT(centreError(few[0].edges[k - 1], h, k), 0.03) << k;
    }
    // A fifth level makes it a spiral: reported as one, nothing apart.
    front.push_back(radialLine(h, h.angleOf(5), h.zOf(5)));
    few.clear();
    EXPECT_EQ(findSpirals(front, {}, p, &few).size(), 1u);
    EXPECT_TRUE(few.empty());
}

// With four seen levels the rise rests on them alone: a level put back between them is allowed
// only when asked (few_max_missing_levels); by default such a helix is not reported (dev2 r0101).
TEST(SpiralSearch, AHelixOfFourSeenLevelsWithAGapIsReportedOnlyWhenGapsAreAllowed) {
    Helix h;
    std::vector<LineSegment> front;
    for (int k : {1, 2, 4, 5}) front.push_back(radialLine(h, h.angleOf(k), h.zOf(k)));
    SpiralSearchParams p = paramsFor(h);
    p.few_seen_levels = 4;
    std::vector<SpiralFlight> few;
    EXPECT_TRUE(findSpirals(front, {}, p, &few).empty());
    EXPECT_TRUE(few.empty());
    p.few_max_missing_levels = 1;
    EXPECT_TRUE(findSpirals(front, {}, p, &few).empty());
    ASSERT_EQ(few.size(), 1u);
    ASSERT_EQ(few[0].edges.size(), 5u);
    EXPECT_EQ(few[0].seen_levels, 4);
    EXPECT_EQ(few[0].edges[2].num_points, 0);  // level 3 put back
    EXPECT_NEAR(few[0].edges[2].z, h.zOf(3), 0.005);
}

// Rises of 0.10-0.11 m (below condition 1's 0.11 m) read 0.093-0.107 m: a helix seen at every
// level with rises of 0.102 m is a spiral (dev3 r0068 read aliased, at 1.5 rises, before).
TEST(SpiralSearch, FindsASpiralWhoseRiseReadsJustBelowConditionOne) {
    Helix h;
    h.rise = 0.102;
    h.step = 30.0 * kDeg;
    std::vector<LineSegment> front;
    for (int k = 1; k <= 7; ++k) front.push_back(radialLine(h, h.angleOf(k), h.zOf(k)));
    const auto spirals = findSpirals(front, {}, paramsFor(h));
    ASSERT_EQ(spirals.size(), 1u);
    const SpiralFlight& f = spirals[0];
    ASSERT_EQ(f.edges.size(), 7u);
    EXPECT_NEAR(f.step_angle_rad, h.step, 1.0 * kDeg);
    for (int k = 1; k <= 7; ++k) EXPECT_LT(centreError(f.edges[k - 1], h, k), 0.03) << k;
}

// Below condition 1 a helix may put back at most one unseen level: a finer helix through a
// spiral's nosings indexes more levels only by putting unseen ones back (dev2 r0066). The same
// lines with a rise within condition 1 are a spiral.
TEST(SpiralSearch, ALowRiseHelixPuttingBackTwoLevelsIsNoSpiral) {
    for (double rise : {0.100, 0.125}) {
        Helix h;
        h.rise = rise;
        h.step = 30.0 * kDeg;
        std::vector<LineSegment> front;
        for (int k : {1, 2, 4, 6, 7}) front.push_back(radialLine(h, h.angleOf(k), h.zOf(k)));
        const auto spirals = findSpirals(front, {}, paramsFor(h));
        if (rise < paramsFor(h).min_rise_m) {
            EXPECT_TRUE(spirals.empty()) << rise;
        } else {
            ASSERT_EQ(spirals.size(), 1u) << rise;
            EXPECT_EQ(spirals[0].edges.size(), 7u);
            EXPECT_EQ(spirals[0].seen_levels, 5);
        }
    }
}

TEST(SpiralSearch, TurnsBackEdgesOntoTheirNosings) {
    // Treads above a level LiDAR: some levels are seen only by their back edge, where the next
    // wedge rises (at height z_k, the angle of nosing k+1).
    Helix h;
    h.step = -24.0 * kDeg;  // clockwise ascent
    std::vector<LineSegment> lines;
    for (int k : {1, 2, 3}) lines.push_back(radialLine(h, h.angleOf(k), h.zOf(k)));
    for (int k : {4, 5, 6, 7}) lines.push_back(radialLine(h, h.angleOf(k + 1), h.zOf(k)));
    const auto spirals = findSpirals({}, lines, paramsFor(h));
    ASSERT_EQ(spirals.size(), 1u);
    const SpiralFlight& f = spirals[0];
    ASSERT_EQ(f.edges.size(), 7u);
    for (int k = 1; k <= 7; ++k) EXPECT_LT(centreError(f.edges[k - 1], h, k), 0.03) << k;
}

TEST(SpiralSearch, BackEdgesAboveAnUnseenLevelAreNotReadAsNosingsOneStepOn) {
    // Nosings 1-4 below a level HDL-32, level 5 unseen, levels 6-9 seen by their back edges only
    // (at height z_k, the angle of nosing k+1), every line read 3-7 cm low as in dev5 r1113. A
    // helix through both, 9 levels with level 5 put back, reads nosings 6-9 a step further on (its
    // gap turns three steps over two levels): one rise off in height at their places.
    Helix h;
    h.step = 32.8 * kDeg;
    h.rise = 0.121;
    h.inner = 0.15;
    h.outer = 0.77;
    h.phi0 = -139.0 * kDeg;
    std::vector<LineSegment> front, back;
    // [m] read low; level 5 is put back between its neighbours' readings
    const double low[] = {0, 0.027, 0.053, 0.064, 0.067, 0.0525, 0.038, 0.031, 0.038, 0.046};
    for (int k : {1, 2, 3, 4}) front.push_back(radialLine(h, h.angleOf(k), h.zOf(k) - low[k]));
    for (int k : {6, 7, 8, 9}) back.push_back(radialLine(h, h.angleOf(k + 1), h.zOf(k) - low[k]));
    const auto spirals = findSpirals(front, back, paramsFor(h));
    ASSERT_EQ(spirals.size(), 1u);
    const SpiralFlight& f = spirals[0];
    ASSERT_EQ(f.edges.size(), 9u);
    EXPECT_NEAR(f.step_angle_rad, h.step, 1.5 * kDeg);
    for (int k = 1; k <= 9; ++k) {
        EXPECT_NEAR(f.edges[k - 1].z, h.zOf(k) - low[k], 0.03) << k;
        EXPECT_LT(centreError(f.edges[k - 1], h, k), 0.05) << k;
    }
}

TEST(SpiralSearch, SettlesOnTheNosingsWhenBothAreSeenAtSomeLevels) {
    // A gently turning spiral (21 deg per step): the lowest level seen by its back edge only, two
    // by their nosings, the top two by both. A first helix through all of them (9 deg tolerance)
    // lies between nosings and back edges and turns the top nosings back a step.
    Helix h;
    h.step = -21.0 * kDeg;
    h.rise = 0.17;
    h.inner = 0.22;
    h.outer = 1.55;
    h.phi0 = 10.0 * kDeg;
    std::vector<LineSegment> front, back;
    front.push_back(radialLine(h, h.angleOf(2), h.zOf(1)));
    for (int k : {4, 5}) {
        front.push_back(radialLine(h, h.angleOf(k), h.zOf(k)));
        back.push_back(radialLine(h, h.angleOf(k), h.zOf(k) - 0.002));
    }
    for (int k : {7, 8}) {
        front.push_back(radialLine(h, h.angleOf(k), h.zOf(k)));
        back.push_back(radialLine(h, h.angleOf(k + 1), h.zOf(k) - 0.015));
    }
    const auto spirals = findSpirals(front, back, paramsFor(h));
    ASSERT_EQ(spirals.size(), 1u);
    const SpiralFlight& f = spirals[0];
    ASSERT_EQ(f.edges.size(), 8u);
    EXPECT_NEAR(f.step_angle_rad, std::abs(h.step), 1.5 * kDeg);
    for (int k = 1; k <= 8; ++k) EXPECT_LT(centreError(f.edges[k - 1], h, k), 0.05) << k;
}

TEST(SpiralSearch, FillsLevelsOfAnEstablishedHelixWithLinesPartlyHiddenByTheColumn) {
    const Helix h = closeViewHelix();
    const auto spirals = findSpirals(closeViewLines(h, 3), {}, paramsFor(h));
    ASSERT_EQ(spirals.size(), 1u);
    const SpiralFlight& f = spirals[0];
    ASSERT_EQ(f.edges.size(), 6u);
    EXPECT_EQ(f.seen_levels, 6);
    EXPECT_LT((f.axis - h.axis).norm(), 0.01);
    for (int k = 1; k <= 6; ++k) {
        EXPECT_NEAR(f.edges[k - 1].z, h.zOf(k), 1e-9) << k;
        EXPECT_LT(angleError(f.edges[k - 1], h, k), 3.0 * kDeg) << k;
    }
}

TEST(SpiralSearch, LinesPartlyHiddenByTheColumnAloneMakeNoSpiral) {
    const Helix h = closeViewHelix();
    // Two levels under the strict bounds are no established helix: the three looser lines on it
    // must not complete one.
    EXPECT_TRUE(findSpirals(closeViewLines(h, 2), {}, paramsFor(h)).empty());
    std::vector<LineSegment> hidden;
    for (int k = 1; k <= 6; ++k) hidden.push_back(outerPartOf(h, h.angleOf(k), h.zOf(k), 0.6));
    EXPECT_TRUE(findSpirals(hidden, {}, paramsFor(h)).empty());
}

/// Lines of levels `first`..`last` of a 25 deg spiral (an elevation map of a spiral turning more
/// than once keeps only its upper wedges), the lowest `lowest_dz` [m] off its level.
std::vector<LineSegment> upperLevelLines(const Helix& h, int first, int last, double lowest_dz) {
    std::vector<LineSegment> lines;
    for (int k = first; k <= last; ++k)
        lines.push_back(radialLine(h, h.angleOf(k), h.zOf(k) + (k == first ? lowest_dz : 0.0)));
    return lines;
}

TEST(SpiralSearch, ASpiralSeenOnlyHighIsPutBackDownToTheFloor) {
    Helix h;
    h.step = 25.0 * kDeg;
    h.phi0 = 10.0 * kDeg;
    // Levels 7-12 seen (1.26 m and more above the floor, past max_first_height_m).
    const auto spirals = findSpirals(upperLevelLines(h, 7, 12, 0.0), {}, paramsFor(h));
    ASSERT_EQ(spirals.size(), 1u);
    EXPECT_EQ(spirals[0].seen_levels, 6);
    expectLevelsOnTheHelix(spirals[0], h, 12, [](int k) { return k < 7; });
}

TEST(SpiralSearch, AHighSpiralMustHoldSixLevelsAWholeNumberOfRisesAboveTheFloor) {
    Helix h;
    h.step = 25.0 * kDeg;
    h.phi0 = 10.0 * kDeg;
    EXPECT_TRUE(findSpirals(upperLevelLines(h, 8, 12, 0.0), {}, paramsFor(h)).empty());  // 5 levels
    // The whole helix half a rise off the floor's height: no stair standing on that floor.
    std::vector<LineSegment> off_floor = upperLevelLines(h, 7, 12, 0.0);
    for (LineSegment& l : off_floor) l.z += 0.5 * h.rise;
    EXPECT_TRUE(findSpirals(off_floor, {}, paramsFor(h)).empty());
    // Levels 11-16: ten levels below would be put back, more than allowed.
    EXPECT_TRUE(findSpirals(upperLevelLines(h, 11, 16, 0.0), {}, paramsFor(h)).empty());
}

/// Tread k's outer rim seen as a line (an elevation map cropped at the spiral): the chord of the
/// outer arc from nosing k's angle to nosing k+1's.
LineSegment rimChord(const Helix& h, int k) {
    const Eigen::Vector2d a = h.axis + h.outer * Eigen::Vector2d(std::cos(h.angleOf(k)), std::sin(h.angleOf(k)));
    const Eigen::Vector2d b =
        h.axis + h.outer * Eigen::Vector2d(std::cos(h.angleOf(k + 1)), std::sin(h.angleOf(k + 1)));
    LineSegment l = radialLine(h, h.angleOf(k), h.zOf(k));
    l.start = a;
    l.end = b;
    const Eigen::Vector2d d = (b - a).normalized();
    Eigen::Vector2d n(d.y(), -d.x());
    if (n.dot(l.start) < 0) n = -n;
    l.rho = n.dot(l.start);
    l.theta = std::atan2(n.y(), n.x());
    return l;
}

TEST(SpiralSearch, FindsASpiralSeenOnlyByItsTreadsOuterRims) {
    Helix h;  // dev r0034: 23 deg per step, rims 1.04 m from the axis
    h.inner = 0.15;
    h.outer = 1.04;
    h.rise = 0.2;
    h.step = -23.0 * kDeg;
    std::vector<LineSegment> lines;
    for (int k = 1; k <= 5; ++k) lines.push_back(rimChord(h, k));
    const auto spirals = findSpirals(lines, {}, paramsFor(h));
    ASSERT_EQ(spirals.size(), 1u);
    const SpiralFlight& f = spirals[0];
    ASSERT_EQ(f.edges.size(), 5u);
    EXPECT_LT((f.axis - h.axis).norm(), 0.01);
    EXPECT_NEAR(f.outer_radius_m, h.outer, 0.01);
    EXPECT_NEAR(f.step_angle_rad, std::abs(h.step), 0.5 * kDeg);
    for (int k = 1; k <= 5; ++k) {
        EXPECT_NEAR(f.edges[k - 1].z, h.zOf(k), 1e-9) << k;
        EXPECT_LT(angleError(f.edges[k - 1], h, k), 1.0 * kDeg) << k;
        EXPECT_LT(centreError(f.edges[k - 1], h, k), 0.02) << k;
    }
    // Four rims are too few, as four nosings are (min_seen_levels).
    lines.pop_back();
    EXPECT_TRUE(findSpirals(lines, {}, paramsFor(h)).empty());
}

TEST(SpiralSearch, NoSpiralInStraightFlightsOrUnorderedRadialLines) {
    const Helix h;
    const SpiralSearchParams p = paramsFor(h);
    std::vector<LineSegment> straight;
    for (int k = 1; k <= 8; ++k) {  // parallel nosings 0.28 m apart: a straight flight
        LineSegment l;
        l.start = {2.0 + 0.28 * k, -0.6};
        l.end = {2.0 + 0.28 * k, 0.6};
        l.z = h.zOf(k);
        l.rho = l.start.x();
        l.theta = 0.0;
        straight.push_back(l);
    }
    EXPECT_TRUE(findSpirals(straight, {}, p).empty());
    // Radial lines about one point whose angles do not grow with height (a shelf's star, clutter).
    std::vector<LineSegment> star;
    const double angles[] = {0, 140, 60, 250, 10, 190, 300, 90};
    for (int k = 1; k <= 8; ++k) star.push_back(radialLine(h, angles[k - 1] * kDeg, h.zOf(k)));
    EXPECT_TRUE(findSpirals(star, {}, p).empty());
    // Three levels only: fewer than min_steps.
    std::vector<LineSegment> three;
    for (int k = 1; k <= 3; ++k) three.push_back(radialLine(h, h.angleOf(k), h.zOf(k)));
    EXPECT_TRUE(findSpirals(three, {}, p).empty());
}

// Lines of another kind added to a search already made (StairDetector's tread nosings): with
// pair_lines, an axis is looked for only through pairs holding one of the first lines, but every
// line may be an inlier.
TEST(SpiralSearch, PairLinesLimitTheAxisPairsNotTheInliers) {
    const Helix h;
    std::vector<LineSegment> lines;
    for (int k = 1; k <= 5; ++k) lines.push_back(radialLine(h, h.angleOf(k), h.zOf(k)));
    SpiralSearchParams p = paramsFor(h);
    p.rim_search = false;
    // Level 3's line first: every pair holding it points at the axis; all five levels are found.
    std::swap(lines[0], lines[2]);
    p.pair_lines = 1;
    auto spirals = findSpirals(lines, {}, p);
    ASSERT_EQ(spirals.size(), 1u);
    EXPECT_EQ(spirals[0].seen_levels, 5);
    // A first line off every helix (a straight nosing far away): no pair holding it makes a spiral,
    // though the other five would.
    LineSegment stray = radialLine(h, h.angleOf(3), h.zOf(3));
    stray.start += Eigen::Vector2d(3.0, 3.0);
    stray.end += Eigen::Vector2d(3.0, 3.0);
    stray.rho = Eigen::Vector2d(std::cos(stray.theta), std::sin(stray.theta)).dot(stray.start);
    if (stray.rho < 0) stray.rho = -stray.rho, stray.theta += M_PI;
    lines.insert(lines.begin(), stray);
    EXPECT_TRUE(findSpirals(lines, {}, p).empty());
    p.pair_lines = 0;
    EXPECT_EQ(findSpirals(lines, {}, p).size(), 1u);
}

// Three seen levels make no spiral, but their axis is glimpsed (where StairDetector looks at the
// treads); where a spiral is found nothing is glimpsed from its lines.
TEST(SpiralSearch, GlimpsesTheAxisOfAHelixOfThreeSeenLevels) {
    const Helix h;
    std::vector<LineSegment> three;
    for (int k = 1; k <= 3; ++k) three.push_back(radialLine(h, h.angleOf(k), h.zOf(k)));
    SpiralGlimpse glimpse;
    EXPECT_TRUE(findSpirals(three, {}, paramsFor(h), nullptr, &glimpse).empty());
    EXPECT_EQ(glimpse.seen_levels, 3);
    EXPECT_LT((glimpse.axis - h.axis).norm(), 0.01);
    // Two levels are no glimpse (a pair alone always points somewhere).
    SpiralGlimpse none;
    three.pop_back();
    findSpirals(three, {}, paramsFor(h), nullptr, &none);
    EXPECT_EQ(none.seen_levels, 0);
}

}  // namespace
}  // namespace stairmap
