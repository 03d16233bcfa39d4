// A chain one edge short of a flight: continued only where the cloud shows the tread above its last
// edge (or below its first, or a rise below the floor in front of it), never on a stage's platform.
// Hand-made edges and clouds.
#include "core/FlightContinuation.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "support/HandMadeNosing.h"

namespace stairmap {
namespace {

constexpr double kRise = 0.17;  // [m]
constexpr double kRun = 0.30;   // [m]

/// A nosing across y in [-0.6, 0.6] at distance x, height z (seen, 20 points).
LineSegment nosing(double x, double z) { return test::nosingAcrossY(x, z, 0.6); }

/// Step k of a flight rising along +x from the floor at z = 0: nosing at x = 1 + (k - 1) run.
LineSegment step(int k) { return nosing(1.0 + (k - 1) * kRun, k * kRise); }

/// Points on a horizontal rectangle x in [x0, x1], y in [-0.6, 0.6] at height z, 2 cm apart.
void addTread(PointCloud& cloud, double x0, double x1, double z) {
    for (double x = x0; x < x1; x += 0.02)
        for (double y = -0.6; y <= 0.6; y += 0.02)
            cloud.emplace_back(float(x), float(y), float(z));
}

/// The flight's treads 1..3 (each one run deep, behind its nosing).
PointCloud threeTreads() {
    PointCloud cloud;
    for (int k = 1; k <= 3; ++k) addTread(cloud, 1.0 + (k - 1) * kRun, 1.0 + k * kRun, k * kRise);
    return cloud;
}

TEST(FlightContinuation, TheTreadAboveTheLastEdgeAddsTheNextNosing) {
    PointCloud cloud = threeTreads();
    addTread(cloud, 1.0 + 3 * kRun, 1.0 + 4 * kRun, 4 * kRise);  // step 4, its nosing line unfound
    const std::vector<LineSegment> edges = {step(1), step(2), step(3)};
    ASSERT_TRUE(treadAboveLastEdge(cloud, edges));
    const LineSegment next = nextNosing(edges);
    EXPECT_NEAR(next.z, 4 * kRise, 1e-6);
    EXPECT_NEAR(next.centre().x(), 1.0 + 3 * kRun, 1e-6);
    EXPECT_NEAR(next.length(), 1.2, 1e-6);
    EXPECT_EQ(next.num_points, 0);
}

TEST(FlightContinuation, AStagesPlatformBehindTheLastEdgeIsNoNextStep) {
    // Two steps and the platform's edge (the generator's two-step stage): flat 4 m behind.
    PointCloud cloud = threeTreads();
    addTread(cloud, 1.0 + 3 * kRun, 5.0, 3 * kRise);
    EXPECT_FALSE(treadAboveLastEdge(cloud, {step(1), step(2), step(3)}));
}

TEST(FlightContinuation, AWallBehindTheLastEdgeIsNoNextStep) {
    PointCloud cloud = threeTreads();
    // A wall one and a half runs behind the last nosing, from the floor up: some of its points lie
    // at the next tread's height, most above it.
    const double x = 1.0 + 3.5 * kRun;
    for (double z = 0.0; z < 2.0; z += 0.02)
        for (double y = -0.6; y <= 0.6; y += 0.02) cloud.emplace_back(float(x), float(y), float(z));
    EXPECT_FALSE(treadAboveLastEdge(cloud, {step(1), step(2), step(3)}));
}

TEST(FlightContinuation, AnIrregularChainIsNotContinued) {
    PointCloud cloud = threeTreads();
    addTread(cloud, 1.0 + 3 * kRun, 1.0 + 4 * kRun, 4 * kRise);
    // The last edge one and a half runs behind the second: no regular flight.
    EXPECT_FALSE(treadAboveLastEdge(cloud, {step(1), step(2), nosing(1.0 + 2.5 * kRun, 3 * kRise)}));
}

TEST(FlightContinuation, ALowRiseIsTakenWithinTheNoiseOfItsMean) {
    // Rises of 0.10 m (a mean of two measured rises reads 0.096-0.107 m on such flights) pass the
    // 0.11 m minimum within its noise; 0.09 m does not.
    for (const double rise : {0.10, 0.09}) {
        PointCloud cloud;
        std::vector<LineSegment> edges;
        for (int k = 1; k <= 4; ++k) addTread(cloud, 1.0 + (k - 1) * kRun, 1.0 + k * kRun, k * rise);
        for (int k = 1; k <= 3; ++k) edges.push_back(nosing(1.0 + (k - 1) * kRun, k * rise));
        EXPECT_EQ(treadAboveLastEdge(cloud, edges), rise > 0.095) << "rise " << rise;
    }
}

/// Points on a vertical rectangle at distance x, y in [-0.6, 0.6], z in [z0, z1], 2 cm apart.
void addRiser(PointCloud& cloud, double x, double z0, double z1) {
    for (double z = z0; z < z1; z += 0.02)
        for (double y = -0.6; y <= 0.6; y += 0.02) cloud.emplace_back(float(x), float(y), float(z));
}

TEST(FlightContinuation, TheNextStepsRiserAboveTheLastEdgeContinuesTheChain) {
    // A level LiDAR below the upper treads: the riser of step 4 seen, its tread not.
    PointCloud cloud = threeTreads();
    addRiser(cloud, 1.0 + 3 * kRun, 3 * kRise, 4 * kRise);
    const std::vector<LineSegment> edges = {step(1), step(2), step(3)};
    EXPECT_TRUE(riserAboveLastEdge(cloud, edges));
    EXPECT_FALSE(treadAboveLastEdge(cloud, edges));  // the cue the tread test misses
    // The riser alone, without the treads in front (a sparse view's hits on it): still a riser.
    PointCloud riser_only;
    addRiser(riser_only, 1.0 + 3 * kRun, 3 * kRise, 4 * kRise);
    EXPECT_TRUE(riserAboveLastEdge(riser_only, edges));
}

TEST(FlightContinuation, AStagesPlatformOrAWallBehindTheLastEdgeIsNoRiser) {
    const std::vector<LineSegment> edges = {step(1), step(2), step(3)};
    PointCloud platform = threeTreads();
    addTread(platform, 1.0 + 3 * kRun, 5.0, 3 * kRise);
    EXPECT_FALSE(riserAboveLastEdge(platform, edges));
    // A wall one run behind the platform's edge, from the platform up to 2 m: its points at the
    // riser's heights are outnumbered by those above.
    PointCloud wall = threeTreads();
    addRiser(wall, 1.0 + 3 * kRun, 3 * kRise, 2.0);
    EXPECT_FALSE(riserAboveLastEdge(wall, edges));
    // A riser too low (a second stage's edge half a rise up) or in the wrong place (two runs
    // behind) is not the next step's.
    PointCloud low = threeTreads();
    addRiser(low, 1.0 + 3 * kRun, 3 * kRise, 3.2 * kRise);
    EXPECT_FALSE(riserAboveLastEdge(low, edges));
    PointCloud far = threeTreads();
    addRiser(far, 1.0 + 4 * kRun, 3 * kRise, 4 * kRise);
    EXPECT_FALSE(riserAboveLastEdge(far, edges));
}

// A two-step stage's platform edge read as a riser hit, 0.3 rises under the platform (negatives
// of seed 26026): the platform then lies in the riser window's heights, one run behind the edge,
// and goes on behind it; a riser is a face with the next tread a rise higher behind it.
TEST(FlightContinuation, APlatformBehindALastEdgeReadLowIsNoRiser) {
    const std::vector<LineSegment> read_low = {step(1), step(2),
                                               nosing(1.0 + 2 * kRun, 2.7 * kRise)};
    PointCloud platform = threeTreads();
    addTread(platform, 1.0 + 3 * kRun, 5.0, 3 * kRise);
    EXPECT_FALSE(riserAboveLastEdge(platform, read_low));
    // the same edges before a riser and the next tread a rise above it
    PointCloud riser = threeTreads();
    addRiser(riser, 1.0 + 3 * kRun, 3 * kRise, 4 * kRise);
    addTread(riser, 1.0 + 3 * kRun, 1.0 + 4 * kRun, 4 * kRise);
    EXPECT_TRUE(riserAboveLastEdge(riser, read_low));
}

TEST(FlightContinuation, AnIrregularChainIsNotContinuedByARiser) {
    PointCloud cloud = threeTreads();
    addRiser(cloud, 1.0 + 3 * kRun, 3 * kRise, 4 * kRise);
    EXPECT_FALSE(
        riserAboveLastEdge(cloud, {step(1), step(2), nosing(1.0 + 2.5 * kRun, 3 * kRise)}));
}

TEST(FlightContinuation, TheTreadBelowAFirstEdgeTwoRisesUpAddsThePreviousNosing) {
    PointCloud cloud = threeTreads();
    addTread(cloud, 1.0 + 3 * kRun, 1.0 + 4 * kRun, 4 * kRise);
    const std::vector<LineSegment> edges = {step(2), step(3), step(4)};  // step 1's line unfound
    ASSERT_TRUE(treadBelowFirstEdge(cloud, edges, 0.0));
    const LineSegment previous = previousNosing(edges);
    EXPECT_NEAR(previous.z, kRise, 1e-6);
    EXPECT_NEAR(previous.centre().x(), 1.0, 1e-6);
}

TEST(FlightContinuation, TheFloorInFrontOfTheFirstEdgeIsNoStepBelow) {
    // The same chain two rises up, but the floor runs up to it: a platform's front, no step.
    PointCloud cloud;
    addTread(cloud, 0.0, 1.0 + kRun, 0.0);
    for (int k = 2; k <= 4; ++k) addTread(cloud, 1.0 + (k - 1) * kRun, 1.0 + k * kRun, k * kRise);
    EXPECT_FALSE(treadBelowFirstEdge(cloud, {step(2), step(3), step(4)}, 0.0));
    // ...and a chain whose first edge is one rise up has no step missing below it.
    EXPECT_FALSE(treadBelowFirstEdge(threeTreads(), {step(1), step(2), step(3)}, 0.0));
}

TEST(FlightContinuation, ALandingAStepAboveTheFloorInFrontOfTheFirstEdgeStartsAFlight) {
    // Three rises from a landing 0.12 m above the floor (one rise below the first edge, seen in
    // front of it): the upper part of a flight split by the landing.
    const double landing = 0.12;
    PointCloud cloud;
    addTread(cloud, 0.0, 1.0, landing);
    for (int k = 1; k <= 3; ++k)
        addTread(cloud, 1.0 + (k - 1) * kRun, 1.0 + k * kRun, landing + k * kRise);
    std::vector<LineSegment> edges;
    for (int k = 1; k <= 3; ++k) edges.push_back(nosing(1.0 + (k - 1) * kRun, landing + k * kRise));
    EXPECT_TRUE(startsFromRaisedLanding(cloud, edges, 0.0));
    // The same surface seen from a floor 5 cm under it: no step up to it, a stage.
    EXPECT_FALSE(startsFromRaisedLanding(cloud, edges, landing - 0.05));
}

TEST(FlightContinuation, AStageOnTheFloorStartsNoFlightFromALanding) {
    PointCloud cloud = threeTreads();
    addTread(cloud, 0.0, 1.0, 0.0);
    EXPECT_FALSE(startsFromRaisedLanding(cloud, {step(1), step(2), step(3)}, 0.0));
}

TEST(FlightContinuation, ATreadARiseBelowTheFloorInFrontOfItsNosingAddsThatNosing) {
    // A flight rising from a sunken area one rise below the floor: its nosing at the floor's
    // height (x = 1 - run, a ground line, never searched), the floor-high tread behind it, the
    // sunken area's floor in front of it.
    PointCloud cloud = threeTreads();
    addTread(cloud, 1.0 - kRun, 1.0, 0.0);
    addTread(cloud, 0.0, 1.0 - kRun, -kRise);
    const std::vector<LineSegment> edges = {step(1), step(2), step(3)};
    ASSERT_TRUE(floorNosingAbovePit(cloud, edges, 0.0));
    const LineSegment floor_nosing = previousNosing(edges);
    EXPECT_NEAR(floor_nosing.z, 0.0, 1e-6);
    EXPECT_NEAR(floor_nosing.centre().x(), 1.0 - kRun, 1e-6);
}

TEST(FlightContinuation, TheFloorInFrontOfTheFirstStepIsNoPit) {
    // A flight from the floor: the floor in front of its first nosing, nothing below it.
    PointCloud cloud = threeTreads();
    addTread(cloud, 0.0, 1.0, 0.0);
    EXPECT_FALSE(floorNosingAbovePit(cloud, {step(1), step(2), step(3)}, 0.0));
    // ...and a chain two rises up has no nosing at the floor's height one run in front of it.
    PointCloud sunken = threeTreads();
    addTread(sunken, 1.0 + 3 * kRun, 1.0 + 4 * kRun, 4 * kRise);
    addTread(sunken, 0.0, 1.0, -kRise);
    EXPECT_FALSE(floorNosingAbovePit(sunken, {step(2), step(3), step(4)}, 0.0));
}

TEST(FlightContinuation, NothingSeenBeyondTheLastEdgeIsAnUnseenTop) {
    const std::vector<LineSegment> edges = {step(1), step(2), step(3)};
    EXPECT_TRUE(unseenBeyondLastEdge(threeTreads(), edges));
    // A stage's platform one step beyond: seen.
    PointCloud stage = threeTreads();
    addTread(stage, 1.0 + 3 * kRun, 5.0, 3 * kRise);
    EXPECT_FALSE(unseenBeyondLastEdge(stage, edges));
    // The next tread of a longer flight: seen too (treadAboveLastEdge takes that case).
    PointCloud longer = threeTreads();
    addTread(longer, 1.0 + 3 * kRun, 1.0 + 4 * kRun, 4 * kRise);
    EXPECT_FALSE(unseenBeyondLastEdge(longer, edges));
    // Not for an irregular chain.
    EXPECT_FALSE(
        unseenBeyondLastEdge(threeTreads(), {step(1), step(2), nosing(1.0 + 3.0 * kRun, 3 * kRise)}));
}

TEST(FlightContinuation, NothingAtAnyHeightBeyondTheLastEdgeIsTheEndOfTheView) {
    // A descending flight in the descending search's mirrored z: its "treads" lie below the
    // edges in the real cloud, so any point beyond the last edge, however low, is seen.
    const std::vector<LineSegment> edges = {step(1), step(2), step(3)};
    EXPECT_TRUE(nothingBeyondLastEdge(threeTreads(), edges));
    // A pit's floor far below the last edge: seen (unseenBeyondLastEdge, which looks only at and
    // above the last edge's height, would not see it).
    PointCloud pit = threeTreads();
    addTread(pit, 1.0 + 3 * kRun, 5.0, -1.0);
    EXPECT_TRUE(unseenBeyondLastEdge(pit, edges));
    EXPECT_FALSE(nothingBeyondLastEdge(pit, edges));
    // A point beside the window (past the edge's end) does not count.
    PointCloud beside = threeTreads();
    beside.emplace_back(float(1.0 + 3.5 * kRun), 0.7f, 0.0f);
    EXPECT_TRUE(nothingBeyondLastEdge(beside, edges));
    // Not for an irregular chain.
    EXPECT_FALSE(nothingBeyondLastEdge(threeTreads(),
                                       {step(1), step(2), nosing(1.0 + 3.0 * kRun, 3 * kRise)}));
}

/// The nosing of step k read `low` metres below its height (a riser hit), as a far LiDAR's ring
/// gives it.
LineSegment riserHit(int k, double low) { return nosing(1.0 + (k - 1) * kRun, k * kRise - low); }

TEST(FlightContinuation, LinesEveryOtherStepBeyondAChainOfThreeAreFoundInOrder) {
    // Steps 5, 7 and 9 seen, read low by 2-16 cm on their risers (their heights 1.1-2.5 rises
    // apart, where Algorithm 1 asks two rises within 4 cm), steps 4, 6 and 8 not at all.
    const std::vector<LineSegment> lines = {riserHit(7, 0.02), riserHit(5, 0.10), riserHit(9, 0.16),
                                            step(1),           step(2),           step(3)};
    const std::vector<int> beyond = linesEveryOtherStepBeyond(lines, {step(1), step(2), step(3)});
    EXPECT_EQ(beyond, (std::vector<int>{1, 0, 2}));
}

TEST(FlightContinuation, NoLinesBeyondAStagesPlatformEdge) {
    // A two-step stage: its platform's edge is the chain's last; behind it lie a line at the
    // platform's own height two runs back (a mat's edge) and a shelf's front edge 0.8 m up.
    const std::vector<LineSegment> lines = {nosing(1.0 + 4 * kRun, 3 * kRise + 0.01),
                                            nosing(1.0 + 4 * kRun, 3 * kRise + 0.8)};
    EXPECT_TRUE(linesEveryOtherStepBeyond(lines, {step(1), step(2), step(3)}).empty());
}

TEST(FlightContinuation, ALineTwoStepsBeyondMustBeParallelTwoRunsBackAndBesideTheLastEdge) {
    const std::vector<LineSegment> chain = {step(1), step(2), step(3)};
    // One run back (the next nosing: Algorithm 1's own case) or three runs back: not two steps.
    EXPECT_TRUE(linesEveryOtherStepBeyond({riserHit(4, 0.0)}, chain).empty());
    EXPECT_TRUE(linesEveryOtherStepBeyond({nosing(1.0 + 5 * kRun, 5 * kRise)}, chain).empty());
    // Turned by 20 deg about its centre.
    LineSegment turned = step(5);
    const Eigen::Rotation2Dd r(20.0 * M_PI / 180.0);
    const Eigen::Vector2d c = turned.centre();
    turned.start = c + r * (turned.start - c);
    turned.end = c + r * (turned.end - c);
    turned.theta = r.angle();  // the normal turns with it (theta 0: along +x)
    turned.rho = c.x() * std::cos(turned.theta) + c.y() * std::sin(turned.theta);
    EXPECT_TRUE(linesEveryOtherStepBeyond({turned}, chain).empty());
    // Beside the flight: shifted 1.1 m along the edge (overlapping 0.1 of its 1.2 m).
    LineSegment beside = step(5);
    beside.start.y() += 1.1;
    beside.end.y() += 1.1;
    EXPECT_TRUE(linesEveryOtherStepBeyond({beside}, chain).empty());
    // The same line where it belongs is taken.
    EXPECT_EQ(linesEveryOtherStepBeyond({step(5)}, chain), (std::vector<int>{0}));
}

TEST(FlightContinuation, AChainOfTwoEdgesGetsNoLinesBeyond) {
    // One pair is no regular flight to measure two steps by (the mapping presets' min_steps 3).
    EXPECT_TRUE(linesEveryOtherStepBeyond({step(4)}, {step(1), step(2)}).empty());
    EXPECT_EQ(linesEveryOtherStepBeyond({step(5)}, {step(1), step(2), step(3)}),
              (std::vector<int>{0}));
}

TEST(FlightContinuation, AnIrregularChainGetsNoLinesBeyond) {
    EXPECT_TRUE(linesEveryOtherStepBeyond({step(5)},
                                          {step(1), step(2), nosing(1.0 + 2.5 * kRun, 3 * kRise)})
                    .empty());
}

/// Points on the risers under steps 1..3 (x = their nosings), 2 cm apart, y in [-0.6, 0.6].
void addRisers(PointCloud& cloud) {
    for (int k = 1; k <= 3; ++k)
        for (double z = (k - 1) * kRise; z < k * kRise; z += 0.02)
            for (double y = -0.6; y <= 0.6; y += 0.02)
                cloud.emplace_back(float(1.0 + (k - 1) * kRun), float(y), float(z));
}

TEST(FlightContinuation, ARampThroughTheEdgesIsNoStair) {
    // A ramp rising one rise per run through the three edges' lines (a LiDAR's rings on it give
    // such edges), its points 2 cm apart with +-1 cm of noise.
    PointCloud ramp;
    int i = 0;
    for (double x = 0.9; x < 1.0 + 3 * kRun; x += 0.02)
        for (double y = -0.6; y <= 0.6; y += 0.02, ++i)
            ramp.emplace_back(float(x), float(y),
                              float(kRise + (x - 1.0) * kRise / kRun + ((i % 3) - 1) * 0.01));
    EXPECT_TRUE(treadsRiseAlongTheRun(ramp, {step(1), step(2), step(3)}));
}

TEST(FlightContinuation, AStairsTreadsAndRisersOrItsRisersAloneAreNoRamp) {
    const std::vector<LineSegment> edges = {step(1), step(2), step(3)};
    PointCloud stair = threeTreads();
    addRisers(stair);
    EXPECT_FALSE(treadsRiseAlongTheRun(stair, edges));
    PointCloud risers;  // a far LiDAR's riser hits
    addRisers(risers);
    EXPECT_FALSE(treadsRiseAlongTheRun(risers, edges));
    EXPECT_FALSE(treadsRiseAlongTheRun(threeTreads(), edges));
    // Too few points to tell: no ramp.
    PointCloud few;
    for (int k = 0; k < 10; ++k) few.emplace_back(float(1.0 + 0.05 * k), 0.0f, float(kRise));
    EXPECT_FALSE(treadsRiseAlongTheRun(few, edges));
}

}  // namespace
}  // namespace stairmap
