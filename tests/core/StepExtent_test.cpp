// Widths across the full visible tread and the side kinds, against clouds whose treads, walls and
// open sides the test builds itself.
#include "core/StepExtent.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/StairDetector.h"
#include "core/StaircaseGeometry.h"
#include "support/SyntheticScenes.h"

namespace stairmap {
namespace {

constexpr double kRise = 0.17, kRun = 0.30, kHalfWidth = 0.8, kFloor = -0.5, kX0 = 2.0;
constexpr int kSteps = 6;  // nosings; the last is the landing's

double nosingX(int k) { return kX0 + k * kRun; }
double treadZ(int k) { return kFloor + (k + 1) * kRise; }

/// Points of a flight along +x (left = +y), every 2 cm: treads between y_lo and y_hi (the part
/// the view covers), optionally a wall on the left (y = +0.8 .. +0.85) and the floor on the right.
PointCloud flightCloud(double y_lo, bool left_wall, bool right_floor) {
    PointCloud c;
    for (int k = 0; k < kSteps; ++k) {
        const double x_end = k + 1 < kSteps ? nosingX(k + 1) : nosingX(k) + 1.0;
        for (double x = nosingX(k); x < x_end; x += 0.02) {
            for (double y = y_lo; y <= kHalfWidth; y += 0.02)
                c.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(treadZ(k)));
            for (double z = treadZ(k); left_wall && z < treadZ(k) + 1.2; z += 0.04)
                c.emplace_back(static_cast<float>(x), static_cast<float>(kHalfWidth + 0.03), static_cast<float>(z));
            for (double y = -kHalfWidth - 0.6; right_floor && y < -kHalfWidth; y += 0.02)
                c.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(kFloor));
        }
    }
    return c;
}

/// The flight as a chain of nosing pieces 0.4 m long (y from -0.1 to 0.3), as broken lines give.
Staircase pieces() {
    Staircase s;
    for (int k = 0; k < kSteps; ++k) {
        StairEdge e;
        e.start = {nosingX(k), 0.3, treadZ(k)};  // left end first (heading +x)
        e.end = {nosingX(k), -0.1, treadZ(k)};
        s.steps.push_back(e);
    }
    estimateGeometry(s);
    return s;
}

TEST(StepExtent, PiecesGrowToTheWholeTreadBetweenAWallAndAnOpenSide) {
    Staircase s = pieces();
    ASSERT_NEAR(s.step_width, 0.4, 1e-9);
    measureStepExtents(flightCloud(-kHalfWidth, true, true), s);
    EXPECT_EQ(s.left_side, StairSide::Wall);
    EXPECT_EQ(s.right_side, StairSide::Open);
    // within the 8 cm: the bin holding the wall's foot (3 cm out) counts as tread
    EXPECT_NEAR(s.step_width, 2 * kHalfWidth, 0.08);
    for (int k = 0; k + 1 < kSteps; ++k) {  // the landing's edge is not measured
        EXPECT_NEAR(s.steps[k].start.y(), kHalfWidth, 0.06) << "step " << k;
        EXPECT_NEAR(s.steps[k].end.y(), -kHalfWidth, 0.04) << "step " << k;
        EXPECT_NEAR(s.steps[k].start.x(), nosingX(k), 1e-9);
        EXPECT_NEAR(s.steps[k].start.z(), treadZ(k), 1e-9);
    }
    EXPECT_NEAR(s.step_height, kRise, 1e-9);
    EXPECT_NEAR(s.step_depth, kRun, 1e-9);
}

TEST(StepExtent, ADenseTreadEndsWhereItsOutermostPointsLieNotHalfABinBeyond) {
    // Treads sampled every centimetre between open sides (the floor seen beyond both ends): each
    // step's ends lie on the outermost tread points' bins, so on average they lie on the tread's
    // ends. (The bins' outer boundaries read every end 1.25 cm out on average.)
    PointCloud c;
    for (int k = 0; k < kSteps; ++k) {
        const double x_end = k + 1 < kSteps ? nosingX(k + 1) : nosingX(k) + 1.0;
        for (double x = nosingX(k); x < x_end; x += 0.02)
            for (double y = -kHalfWidth - 0.6; y <= kHalfWidth + 0.6; y += 0.01) {
                const bool tread = std::abs(y) <= kHalfWidth;
                c.emplace_back(static_cast<float>(x), static_cast<float>(y),
                               static_cast<float>(tread ? treadZ(k) : kFloor));
            }
    }
    Staircase s = pieces();
    measureStepExtents(c, s);
    EXPECT_EQ(s.left_side, StairSide::Open);
    EXPECT_EQ(s.right_side, StairSide::Open);
    double overshoot = 0.0;  // [m] mean over the measured ends, outwards positive
    int ends = 0;
    for (int k = 0; k + 1 < kSteps; ++k) {  // the landing's edge is not measured
        overshoot += (s.steps[k].start.y() - kHalfWidth) + (-kHalfWidth - s.steps[k].end.y());
        ends += 2;
    }
    EXPECT_NEAR(overshoot / ends, 0.0, 0.006);
    EXPECT_NEAR(s.step_width, 2 * kHalfWidth, 0.02);
}

TEST(StepExtent, ASideTheViewDoesNotCoverIsUnseenAndTheWidthIsWhatWasSeen) {
    Staircase s = pieces();
    measureStepExtents(flightCloud(-0.4, false, false), s);  // nothing right of y = -0.4
    EXPECT_EQ(s.right_side, StairSide::Unseen);
    EXPECT_EQ(s.left_side, StairSide::Unseen);  // no wall, no floor beyond the left end either
    EXPECT_NEAR(s.step_width, kHalfWidth + 0.4, 0.05);
}

TEST(StepExtent, WithASideUnseenTheFlightIsAsWideAsItsWidestStep) {
    // A wall on the left; on the right each tread is seen to a different point (the floor's edge
    // or a nearer step hides the rest), step 2 to its true end; nothing seen beyond any of them.
    const double seen_to[kSteps] = {-0.2, -0.5, -kHalfWidth, -0.3, -0.1, -0.1};
    PointCloud cloud;
    for (int k = 0; k < kSteps; ++k) {
        const double x_end = k + 1 < kSteps ? nosingX(k + 1) : nosingX(k) + 1.0;
        for (double x = nosingX(k); x < x_end; x += 0.02) {
            for (double y = seen_to[k]; y <= kHalfWidth; y += 0.02)
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(treadZ(k)));
            for (double z = treadZ(k); z < treadZ(k) + 1.2; z += 0.04)
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(kHalfWidth + 0.03), static_cast<float>(z));
        }
    }
    Staircase s = pieces();
    measureStepExtents(cloud, s);
    EXPECT_EQ(s.left_side, StairSide::Wall);
    EXPECT_EQ(s.right_side, StairSide::Unseen);
    std::vector<double> widths;
    for (int k = 0; k + 1 < kSteps; ++k) widths.push_back(s.steps[k].length());
    std::sort(widths.begin(), widths.end());
    ASSERT_LT(widths[widths.size() / 2], 2 * kHalfWidth - 0.2);  // most steps read short
    EXPECT_NEAR(s.step_width, 2 * kHalfWidth, 0.08);
}

TEST(StepExtent, EachSideIsMeasuredWhereTheStepsSeeItEvenOnDifferentSteps) {
    // Walls on both sides; every tread is seen on one half only, the left half on even steps and
    // the right half on odd ones, with a 0.5 m gap in the middle through which the floor 1 m
    // below shows (each step's inner end reads as an open side): every step reads about half the
    // width, but together they see both walls.
    PointCloud cloud;
    for (int k = 0; k < kSteps; ++k) {
        const double x_end = k + 1 < kSteps ? nosingX(k + 1) : nosingX(k) + 1.0;
        const double y_lo = k % 2 == 0 ? 0.25 : -kHalfWidth, y_hi = k % 2 == 0 ? kHalfWidth : -0.25;
        for (double x = nosingX(k); x < x_end; x += 0.02) {
            for (double y = y_lo; y <= y_hi + 1e-9; y += 0.02)
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(y),
                                   static_cast<float>(treadZ(k)));
            for (double y = -0.24; y < 0.24; y += 0.04)
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(y),
                                   static_cast<float>(treadZ(k) - 1.0));
            for (double z = treadZ(k); z < treadZ(k) + 1.2; z += 0.04)
                for (const double y_wall : {kHalfWidth + 0.03, -kHalfWidth - 0.03})
                    cloud.emplace_back(static_cast<float>(x), static_cast<float>(y_wall),
                                       static_cast<float>(z));
        }
    }
    Staircase s;
    for (int k = 0; k < kSteps; ++k) {  // found edges on the seen halves
        StairEdge e;
        const double y0 = k % 2 == 0 ? 0.6 : -0.4, y1 = k % 2 == 0 ? 0.4 : -0.6;
        e.start = {nosingX(k), y0, treadZ(k)};
        e.end = {nosingX(k), y1, treadZ(k)};
        e.num_points = 30;
        s.steps.push_back(e);
    }
    estimateGeometry(s);
    measureStepExtents(cloud, s);
    // Both sides bounded (by the majority of steps: a wall on the left, the gap's drop on the
    // right).
    EXPECT_EQ(s.left_side, StairSide::Wall);
    EXPECT_EQ(s.right_side, StairSide::Open);
    for (int k = 0; k + 1 < kSteps; ++k)  // the landing's edge is not measured
        EXPECT_LT(s.steps[k].length(), kHalfWidth) << "step " << k;
    // As in the first test, the bins holding the walls' feet (3 cm out) count as tread. The steps'
    // own widths (their upper quartile, the rule before) read 0.58 m here.
    EXPECT_NEAR(s.step_width, 2 * kHalfWidth, 0.08);
}

TEST(StepExtent, ASideWhoseEndsScatterIsWhereTheOutermostStepReachesIt) {
    // Open on both sides (the floor 1 m below seen beyond every end). On the right every tread is
    // seen to its end; on the left only step 0 is, the others stop short at scattered points
    // (gaps in far rows: nothing of them beyond, only the floor far below).
    const double left_seen_to[kSteps] = {kHalfWidth, 0.4, 0.25, 0.6, 0.2, 0.2};
    PointCloud cloud;
    for (int k = 0; k < kSteps; ++k) {
        const double x_end = k + 1 < kSteps ? nosingX(k + 1) : nosingX(k) + 1.0;
        for (double x = nosingX(k); x < x_end; x += 0.02) {
            for (double y = -kHalfWidth; y <= left_seen_to[k] + 1e-9; y += 0.02)
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(y),
                                   static_cast<float>(treadZ(k)));
            for (const double side : {-1.0, 1.0})  // the floor below, 0.1-0.3 m beyond the ends
                for (double d = 0.1; d < 0.3; d += 0.04) {
                    const double y = side > 0 ? left_seen_to[k] + d : -kHalfWidth - d;
                    cloud.emplace_back(static_cast<float>(x), static_cast<float>(y),
                                       static_cast<float>(treadZ(k) - 1.0));
                }
        }
    }
    Staircase s = pieces();
    measureStepExtents(cloud, s);
    EXPECT_EQ(s.left_side, StairSide::Open);
    EXPECT_EQ(s.right_side, StairSide::Open);
    // The outer quartile of the left ends (0.6 m) read 1.42 m.
    EXPECT_NEAR(s.step_width, 2 * kHalfWidth, 0.04);
}

/// Points along each nosing line, 2 cm in front of it at the tread's height, from y_lo to y_hi.
void addNosingHits(PointCloud& c, double y_lo, double y_hi) {
    for (int k = 0; k + 1 < kSteps; ++k)
        for (double y = y_lo; y <= y_hi; y += 0.02)
            c.emplace_back(static_cast<float>(nosingX(k) - 0.02), static_cast<float>(y),
                           static_cast<float>(treadZ(k)));
}

/// A far LiDAR ring hits each step along its nosing; the treads' surfaces are seen only in the
/// middle (y -0.1 .. 0.3, where the found pieces lie). Wall on the left, floor on the right.
PointCloud nosingHitsCloud() {
    PointCloud cloud;
    addNosingHits(cloud, -kHalfWidth, kHalfWidth);
    for (int k = 0; k + 1 < kSteps; ++k)
        for (double x = nosingX(k) + 0.05; x < nosingX(k + 1) - 0.05; x += 0.04) {
            for (double y = -0.1; y <= 0.3; y += 0.04)
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(treadZ(k)));
            for (double z = treadZ(k); z < treadZ(k) + 1.2; z += 0.04)
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(kHalfWidth + 0.03), static_cast<float>(z));
            for (double y = -kHalfWidth - 0.3; y < -kHalfWidth - 0.05; y += 0.04)
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(kFloor));
        }
    return cloud;
}

TEST(StepExtent, AStepHitOnlyAlongItsNosingIsMeasuredToTheNosingsEnds) {
    Staircase s = pieces();
    measureStepExtents(nosingHitsCloud(), s);
    EXPECT_NEAR(s.step_width, 2 * kHalfWidth, 0.08);
    EXPECT_EQ(s.left_side, StairSide::Wall);
    EXPECT_EQ(s.right_side, StairSide::Open);
}

TEST(StepExtent, AStraightFlightsStepsAreMeasuredAlongItsCommonDirection) {
    // The pieces' fits are off by +-4 deg in turn (a short piece's angle error): along its own
    // direction each tread's band leaves the nosing line 4 cm off at 0.6 m from the piece, and
    // the step would end there. The flight's mean direction is the true one.
    Staircase s = pieces();
    const double tilt = 4.0 * M_PI / 180.0;
    for (std::size_t k = 0; k < s.steps.size(); ++k) {
        StairEdge& e = s.steps[k];
        const Eigen::Vector3d c = e.centre();
        const double a = (k % 2 == 0 ? 1.0 : -1.0) * tilt, half = 0.5 * e.length();
        const Eigen::Vector3d left(std::sin(a), std::cos(a), 0.0);  // +y turned by a
        e.start = c + half * left;
        e.end = c - half * left;
    }
    estimateGeometry(s);
    measureStepExtents(nosingHitsCloud(), s);
    EXPECT_NEAR(s.step_width, 2 * kHalfWidth, 0.08);
    EXPECT_EQ(s.left_side, StairSide::Wall);
    EXPECT_EQ(s.right_side, StairSide::Open);
    for (int k = 0; k + 1 < kSteps; ++k)  // the edges keep their own directions
        EXPECT_NEAR(std::abs((s.steps[k].end - s.steps[k].start).normalized().x()), std::sin(tilt),
                    1e-6)
            << "step " << k;
}

/// A far ring hits each nosing line in single dashes every 0.4 m across the flight (y = -0.8,
/// -0.4, ... 0.8); the treads' surfaces are seen only in the middle (y -0.1 .. 0.3, where the found
/// pieces lie). With `box`, a box beside the middle stands on every tread at y 0.55-0.65.
PointCloud dashedNosingsCloud(bool box) {
    PointCloud cloud;
    for (int k = 0; k + 1 < kSteps; ++k) {
        for (int d = -2; d <= 2; ++d)
            cloud.emplace_back(static_cast<float>(nosingX(k) - 0.02), static_cast<float>(0.4 * d),
                               static_cast<float>(treadZ(k)));
        for (double x = nosingX(k) + 0.05; x < nosingX(k + 1) - 0.05; x += 0.04) {
            for (double y = -0.1; y <= 0.3; y += 0.04)
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(y),
                                   static_cast<float>(treadZ(k)));
            for (double y = 0.55; box && y <= 0.65; y += 0.02)
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(y),
                                   static_cast<float>(treadZ(k) + 0.3));
        }
    }
    return cloud;
}

TEST(StepExtent, ANosingSeenInDashesIsMeasuredAcrossTheHolesBetweenThem) {
    // dev4 r0207: a far HDL-32 ring hit a descending flight's nosings in dashes 0.3-0.4 m apart;
    // the steps ended at the first hole, 0.43 m of 1.60 m.
    Staircase s = pieces();
    measureStepExtents(dashedNosingsCloud(false), s);
    EXPECT_NEAR(s.step_width, 2 * kHalfWidth, 0.06);
    // Holes only as long as the side band (the walk before): the steps end at the next dash.
    StepExtentParams short_holes;
    short_holes.max_open_gap_m = short_holes.side_band_m;
    Staircase t = pieces();
    measureStepExtents(dashedNosingsCloud(false), t, short_holes);
    EXPECT_LT(t.step_width, 0.9);
}

TEST(StepExtent, ABoxInAHoleBetweenNosingDashesEndsTheStep) {
    // Something rising above the treads in the hole: the steps end at the dash before it and the
    // side is a wall; the other side still reaches its last dash.
    Staircase s = pieces();
    measureStepExtents(dashedNosingsCloud(true), s);
    EXPECT_NEAR(s.step_width, 1.2, 0.06);
    EXPECT_EQ(s.left_side, StairSide::Wall);
}

TEST(StepExtent, AStringerBesideTheTreadsIsNoPartOfTheSteps) {
    // An open-sided flight with a stringer just beyond the treads' right ends: a 5 cm wide beam
    // whose top rises with the flight and crosses each nosing's height at the nosing.
    PointCloud cloud = flightCloud(-kHalfWidth, false, false);
    const double slope = kRise / kRun;
    for (double x = nosingX(0) - 0.2; x < nosingX(kSteps - 1); x += 0.02)
        for (double y = -kHalfWidth - 0.08; y <= -kHalfWidth - 0.03; y += 0.01)
            cloud.emplace_back(static_cast<float>(x), static_cast<float>(y),
                               static_cast<float>(treadZ(0) + slope * (x - nosingX(0))));
    Staircase s = pieces();
    measureStepExtents(cloud, s);
    for (int k = 0; k + 1 < kSteps; ++k)
        EXPECT_NEAR(s.steps[k].end.y(), -kHalfWidth, 0.03) << "step " << k;
}

TEST(StepExtent, EmptyCloudAndTinyStaircasesChangeNothing) {
    Staircase s = pieces();
    measureStepExtents({}, s);
    EXPECT_NEAR(s.step_width, 0.4, 1e-9);
    EXPECT_EQ(s.left_side, StairSide::Unseen);
    Staircase empty;
    measureStepExtents(flightCloud(-kHalfWidth, true, true), empty);
    EXPECT_TRUE(empty.steps.empty());
}

TEST(StepExtent, DegenerateEdgesAndNonFinitePointsAreSkipped) {
    Staircase s = pieces();
    s.steps[2].end = s.steps[2].start;  // zero length: no direction to measure along
    PointCloud cloud = flightCloud(-kHalfWidth, true, true);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    cloud.emplace_back(nan, 0.0f, 0.0f);
    cloud.emplace_back(2.5f, nan, -0.1f);
    measureStepExtents(cloud, s);
    EXPECT_NEAR(s.steps[2].length(), 0.0, 1e-12);
    EXPECT_NEAR(s.steps[1].length(), 2 * kHalfWidth, 0.08);
    EXPECT_EQ(s.left_side, StairSide::Wall);
    EXPECT_EQ(s.right_side, StairSide::Open);
}

/// Upright points (a wall, a railing's post) at lateral position y beside step k's tread, from
/// 0.1 m to 1.0 m above it.
void addUprightBeside(PointCloud& c, int k, double y) {
    for (double x = nosingX(k) + 0.05; x < nosingX(k + 1) - 0.05; x += 0.02)
        for (double z = treadZ(k) + 0.1; z < treadZ(k) + 1.0; z += 0.04)
            c.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
}

TEST(StepExtent, AWallSeenBeyondAHoleOnEveryStepBoundsTheSide) {
    // Treads seen from y = -0.2 leftwards (a wall on the left); their right parts hidden (a
    // LiDAR's blind cone, nearer steps), the wall on the right seen beyond the hole.
    PointCloud cloud = flightCloud(-0.2, true, false);
    for (int k = 0; k + 1 < kSteps; ++k) addUprightBeside(cloud, k, -kHalfWidth - 0.03);
    Staircase s = pieces();
    measureStepExtents(cloud, s);
    EXPECT_EQ(s.left_side, StairSide::Wall);
    EXPECT_EQ(s.right_side, StairSide::Wall);
    EXPECT_NEAR(s.step_width, 2 * kHalfWidth, 0.08);
    for (int k = 0; k + 1 < kSteps; ++k)
        EXPECT_NEAR(s.steps[k].end.y(), -kHalfWidth, 0.05) << "step " << k;
    // rise and run from the treads as seen, the edges' move sideways changes neither
    EXPECT_NEAR(s.step_height, kRise, 1e-9);
    EXPECT_NEAR(s.step_depth, kRun, 1e-9);
}

TEST(StepExtent, UprightsBesideFewStepsOrOutOfLineLeaveTheSideUnseen) {
    const PointCloud treads = flightCloud(-0.2, true, false);
    PointCloud two = treads;  // beside two steps only (a box, a bin)
    addUprightBeside(two, 1, -kHalfWidth - 0.03);
    addUprightBeside(two, 2, -kHalfWidth - 0.03);
    PointCloud scattered = treads;  // beside every step, but not in line (furniture)
    for (int k = 0; k + 1 < kSteps; ++k) addUprightBeside(scattered, k, -0.5 - 0.15 * k);
    PointCloud beyond_drop = treads;  // in line, but a drop is seen in the hole before it
    for (int k = 0; k + 1 < kSteps; ++k) {
        addUprightBeside(beyond_drop, k, -kHalfWidth - 0.03);
        for (double x = nosingX(k) + 0.05; x < nosingX(k + 1) - 0.05; x += 0.02)
            beyond_drop.emplace_back(static_cast<float>(x), -0.6f, static_cast<float>(kFloor));
    }
    for (const PointCloud* cloud : {&two, &scattered, &beyond_drop}) {
        Staircase s = pieces();
        measureStepExtents(*cloud, s);
        EXPECT_EQ(s.right_side, StairSide::Unseen);
        EXPECT_NEAR(s.step_width, kHalfWidth + 0.2, 0.08);  // the left wall's foot counts as tread
    }
}

TEST(StepExtent, NoUprightBeyondTheHoleLeavesTheSideUnseenWhateverTheStepCountAsked) {
    // Even asked for no agreeing steps at all, an empty hole bounds nothing (and reads no median
    // of nothing).
    StepExtentParams p;
    p.min_bridge_steps = 0;
    Staircase s = pieces();
    measureStepExtents(flightCloud(-0.2, true, false), s, p);
    EXPECT_EQ(s.right_side, StairSide::Unseen);
    EXPECT_NEAR(s.step_width, kHalfWidth + 0.2, 0.08);
}

TEST(StepExtent, TheNextStepsFrontSpreadOverTheTreadByRangeNoiseIsNoWall) {
    // A far view: each tread seen in strips 0.1 m wide with 0.2 m holes between, and the next
    // step's front (its riser's top, an open tread's edge) spread 6 cm onto the tread by range
    // noise along the flight. A wall on the left, the floor beyond the right end.
    PointCloud cloud;
    for (int k = 0; k + 1 < kSteps; ++k)
        for (double x = nosingX(k) + 0.02; x < nosingX(k + 1) - 0.08; x += 0.02) {
            for (double y0 = -kHalfWidth; y0 < kHalfWidth; y0 += 0.3)
                for (double y = y0; y <= y0 + 0.1; y += 0.02)
                    cloud.emplace_back(static_cast<float>(x), static_cast<float>(y),
                                       static_cast<float>(treadZ(k)));
            for (double z = treadZ(k); z < treadZ(k) + 1.2; z += 0.04)
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(kHalfWidth + 0.03),
                                   static_cast<float>(z));
            for (double y = -kHalfWidth - 0.3; y < -kHalfWidth - 0.05; y += 0.04)
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(y),
                                   static_cast<float>(kFloor));
        }
    for (int k = 0; k + 1 < kSteps; ++k)
        for (double y = -kHalfWidth; y <= kHalfWidth; y += 0.02)
            cloud.emplace_back(static_cast<float>(nosingX(k + 1) - 0.06), static_cast<float>(y),
                               static_cast<float>(treadZ(k) + 0.7 * kRise));
    Staircase s = pieces();
    measureStepExtents(cloud, s);
    EXPECT_NEAR(s.step_width, 2 * kHalfWidth, 0.08);
    EXPECT_EQ(s.left_side, StairSide::Wall);
    EXPECT_EQ(s.right_side, StairSide::Open);
}

TEST(StepExtent, DetectorReportsSidesAndFullWidthOnARayCastScene) {
    // wall on the flight's left, floor visible beyond its right end
    test::SceneOptions o;
    test::SceneBuilder scene(o);
    scene.addFloor();
    test::StairSpec spec;
    spec.width_m = 1.6;
    spec.distance_m = 1.8;
    spec.lateral_m = 0.3;
    const test::StairTruth truth = scene.addStairs(spec);
    const double wall_y = spec.lateral_m + 0.5 * spec.width_m + 0.025;  // 5 cm thick wall
    scene.addWall({1.0, wall_y}, {spec.distance_m + 8 * spec.run_m, wall_y}, 2.5);
    const DetectionResult r = StairDetector().detect(scene.cloud(), o.floor_z);
    ASSERT_EQ(r.staircases.size(), 1u);
    const Staircase& s = r.staircases[0];
    EXPECT_EQ(s.left_side, StairSide::Wall);
    EXPECT_EQ(s.right_side, StairSide::Open);
    EXPECT_NEAR(s.step_width, truth.width_m, 0.08);
}

}  // namespace
}  // namespace stairmap
