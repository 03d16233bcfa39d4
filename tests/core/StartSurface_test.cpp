// The surface a flight starts from pins its nosings' line: a far sparse LiDAR's riser-hit edges
// (each up to one ring spacing low) move onto start + (k + 1) rise, the rise bounded by the edges
// from below and the rays that cleared them from above.
#include "core/StartSurface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/RayClearance.h"
#include "core/StairDetector.h"
#include "support/RingScannedFlight.h"

namespace stairmap {
namespace {

using test::riserTopEdge;
using test::scanFlight;

/// At 4.6 m the rings lie 16 cm apart on a riser, close to the rise: every step is hit at about
/// the same phase.
struct Flight : test::RingScannedFlight {
    Flight() {
        x0 = 4.6;
        run = 0.30;
        rise = 0.18;
    }
};

std::vector<LineSegment> riserTopEdges(const PointCloud& cloud, const Flight& f) {
    std::vector<LineSegment> edges;
    for (int k = 0; k < f.steps - 1; ++k) edges.push_back(riserTopEdge(cloud, f, k));
    return edges;
}

double measuredRise(const std::vector<LineSegment>& edges) {
    return (edges.back().z - edges.front().z) / static_cast<double>(edges.size() - 1);
}

TEST(StartSurface, FarFlightEdgesMoveOntoTheNosingsFromTheFloorInFront) {
    const Flight f;
    const PointCloud cloud = scanFlight(f);
    std::vector<LineSegment> edges = riserTopEdges(cloud, f);
    double worst_before = 0;
    for (int k = 0; k < f.steps - 1; ++k) {
        ASSERT_TRUE(std::isfinite(edges[k].z)) << "riser " << k << " not hit";
        worst_before = std::max(worst_before, f.nosingZ(k) - edges[k].z);
    }
    ASSERT_GT(worst_before, 0.06);  // the case this fixes: riser hits well under their nosings
    const double rise = measuredRise(edges);
    // The rays' bounds alone pin nothing here (the rings in step with the rise).
    std::vector<LineSegment> bounds_only = edges;
    fitEdgesToRayClearance(cloud, rise, f.run, bounds_only);
    double worst_bounds_only = 0;
    for (int k = 0; k < f.steps - 1; ++k)
        worst_bounds_only = std::max(worst_bounds_only, std::abs(f.nosingZ(k) - bounds_only[k].z));
    EXPECT_GT(worst_bounds_only, 0.05);

    const std::optional<double> start = startSurfaceHeight(cloud, edges, rise, f.run);
    ASSERT_TRUE(start.has_value());
    EXPECT_NEAR(*start, f.floor_z, 0.01);
    const std::vector<double> upper = edgeClearances(cloud, edges, rise, f.run);
    ASSERT_TRUE(fitEdgesOnStartSurface(*start, upper, rise, edges));
    for (int k = 0; k < f.steps - 1; ++k)
        EXPECT_NEAR(edges[k].z, f.nosingZ(k), 0.03) << "edge " << k;
    EXPECT_NEAR(measuredRise(edges), f.rise, 0.01);
}

/// The detector on a far flight's ring scan, with or without the floor right in front of it.
class FarFlight : public testing::TestWithParam<bool> {};

TEST_P(FarFlight, TheDetectorReportsItAtItsNosings) {
    Flight f;
    f.steps = 7;
    PointCloud cloud = scanFlight(f);
    if (!GetParam()) {  // the floor in front unseen (a far view's rings see it only beside)
        PointCloud kept;
        for (const auto& q : cloud)
            if (!(q.x() > f.x0 - 1.0 && q.x() < f.x0 - 0.02)) kept.push_back(q);
        cloud = kept;
    }
    const DetectionResult r = StairDetector().detect(cloud, f.floor_z);
    ASSERT_EQ(r.staircases.size(), 1u);
    const Staircase& s = r.staircases.front();
    EXPECT_NEAR(s.step_height, f.rise, 0.01);
    ASSERT_GE(s.steps.size(), 4u);
    EXPECT_NEAR(s.steps.front().centre().x(), f.nosingX(0), 0.05);
    for (std::size_t k = 0; k < s.steps.size(); ++k)
        EXPECT_NEAR(s.steps[k].centre().z(), f.nosingZ(static_cast<int>(k)), 0.035) << "step " << k;
}

INSTANTIATE_TEST_SUITE_P(FloorInFront, FarFlight, testing::Values(true, false));

/// Points of a flat band `dz` under the first edge, `s_from`..`s_to` in front of it (towards the
/// robot at -x), over `half_width` either side of the flight's axis.
void addBand(PointCloud& cloud, double z, double s_from, double s_to, double half_width,
             double x_edge) {
    for (double s = s_from; s <= s_to + 1e-9; s += 0.05)
        for (double y = -half_width; y <= half_width + 1e-9; y += 0.05)
            cloud.emplace_back(static_cast<float>(x_edge - s), static_cast<float>(y),
                               static_cast<float>(z));
}

std::vector<LineSegment> straightEdges(double x0, double z0, double rise, double run, int n) {
    std::vector<LineSegment> edges;
    for (int k = 0; k < n; ++k) {
        LineSegment l;
        l.start = {x0 + k * run, -0.5};
        l.end = {x0 + k * run, 0.5};
        l.z = z0 + k * rise;
        l.rho = x0 + k * run;
        l.num_points = 10;
        edges.push_back(l);
    }
    return edges;
}

TEST(StartSurface, TheFlatBandFillingTheFrontIsTheStart) {
    const std::vector<LineSegment> edges = straightEdges(3.0, -0.15, 0.17, 0.3, 4);
    PointCloud cloud;
    EXPECT_FALSE(startSurfaceHeight(cloud, edges, 0.4, 0.3).has_value());  // nothing seen in front
    addBand(cloud, -0.5, 0.6, 0.8, 0.4, 3.0);  // the floor in front of a platform
    ASSERT_TRUE(startSurfaceHeight(cloud, edges, 0.4, 0.3).has_value());
    EXPECT_NEAR(*startSurfaceHeight(cloud, edges, 0.4, 0.3), -0.5, 1e-6);
    // More than a rise (0.2 m) and 3 cm under the first edge: outside the window.
    EXPECT_FALSE(startSurfaceHeight(cloud, edges, 0.2, 0.3).has_value());
    addBand(cloud, -0.32, 0.1, 0.5, 0.4, 3.0);  // the platform the flight starts from
    EXPECT_NEAR(*startSurfaceHeight(cloud, edges, 0.4, 0.3), -0.32, 1e-6);
    // A riser's foot smeared by an elevation map (one row of cells at an intermediate height
    // right in front of it), a box on the platform (narrow) and points without height change
    // nothing.
    PointCloud more = cloud;
    addBand(more, -0.26, 0.08, 0.08, 0.4, 3.0);
    for (int i = 0; i < 6; ++i) more.emplace_back(2.8f, 0.01f * i, -0.25f);
    more.emplace_back(2.8f, 0.0f, std::nanf(""));
    more.emplace_back(std::nanf(""), 0.0f, -0.32f);
    EXPECT_NEAR(*startSurfaceHeight(more, edges, 0.4, 0.3), -0.32, 1e-6);
    // Beside the flight (beyond its width) nothing counts.
    PointCloud beside;
    addBand(beside, -0.5, 0.1, 0.8, 0.3, 3.0);
    for (auto& q : beside) q.y() += 1.5f;
    EXPECT_FALSE(startSurfaceHeight(beside, edges, 0.4, 0.3).has_value());
}

TEST(StartSurface, TheWindowsBoxHoldsEveryPointItLooksAt) {
    const Flight f;
    const PointCloud cloud = scanFlight(f);
    const std::vector<LineSegment> edges = riserTopEdges(cloud, f);
    const double rise = measuredRise(edges);
    const FlightBox box = startWindowBox(edges, rise, f.run);
    PointCloud inside;
    for (const auto& q : cloud)
        if (box.contains(q)) inside.push_back(q);
    ASSERT_LT(inside.size(), cloud.size() / 2);  // the box crops
    const auto whole = startSurfaceHeight(cloud, edges, rise, f.run);
    ASSERT_TRUE(whole.has_value());
    EXPECT_EQ(startSurfaceHeight(inside, edges, rise, f.run), whole);
    // No window (one edge): an empty box, also once its top is raised.
    FlightBox none = startWindowBox({edges.front()}, rise, f.run);
    none.z_hi += 2.0;
    for (const auto& q : cloud) EXPECT_FALSE(none.contains(q));
    EXPECT_FALSE(none.contains(Eigen::Vector3f(0.0f, 0.0f, 1.5f)));
}

TEST(StartSurface, ANoisyFloorIsSeenWholeNotByTheTailOfItsNoise) {
    // A depth camera's floor at -0.5 (1.5 cm noise) in front of a flight of 0.11 m rises whose
    // first edge reads 1 cm low: the floor, not its upper tail, is the start, and nothing moves.
    const std::vector<LineSegment> edges = straightEdges(3.0, -0.40, 0.11, 0.3, 4);
    PointCloud cloud;
    std::mt19937 rng(7);
    std::normal_distribution<float> noise(0.0f, 0.015f);
    for (double s = 0.06; s <= 0.8; s += 0.02)
        for (double y = -0.4; y <= 0.4; y += 0.02)
            cloud.emplace_back(static_cast<float>(3.0 - s), static_cast<float>(y),
                               -0.5f + noise(rng));
    const std::optional<double> start = startSurfaceHeight(cloud, edges, 0.11, 0.3);
    ASSERT_TRUE(start.has_value());
    EXPECT_NEAR(*start, -0.5, 0.01);
    std::vector<LineSegment> moved = edges;
    const std::vector<double> upper(edges.size(), 10.0);
    EXPECT_FALSE(fitEdgesOnStartSurface(*start, upper, 0.11, moved));
}

TEST(StartSurface, UnseenInFrontTheRobotsFloorIsTheStartOfAFirstEdgeTooLowForANosing) {
    const std::vector<LineSegment> edges = straightEdges(3.0, -0.42, 0.2, 0.3, 4);
    const PointCloud nothing_in_front;
    // 8 cm above the floor at -0.5: no nosing of a 0.2 m rise from any surface lies there.
    ASSERT_TRUE(lowEdgesStart(nothing_in_front, edges, 0.2, 0.3, -0.5).has_value());
    EXPECT_EQ(*lowEdgesStart(nothing_in_front, edges, 0.2, 0.3, -0.5), -0.5);
    // A rise above the floor: a nosing, nothing reads low.
    EXPECT_FALSE(lowEdgesStart(nothing_in_front, edges, 0.2, 0.3, -0.62).has_value());
    // Under the floor's height: not a riser hit of a flight from the floor either.
    EXPECT_FALSE(lowEdgesStart(nothing_in_front, edges, 0.2, 0.3, -0.4).has_value());
    // A surface seen in front comes first.
    PointCloud platform;
    addBand(platform, -0.45, 0.1, 0.5, 0.4, 3.0);
    EXPECT_NEAR(*lowEdgesStart(platform, edges, 0.2, 0.3, -0.5), -0.45, 1e-6);
}

TEST(StartSurface, EdgesMoveOnlyWhenLowAndBoundedOnALine) {
    // True nosings: start -0.5, rise 0.18 -> -0.32, -0.14, 0.04, 0.22. Riser hits 2-12 cm low.
    std::vector<LineSegment> low = straightEdges(4.0, -0.32, 0.18, 0.3, 4);
    low[0].z -= 0.08;
    low[1].z -= 0.1;
    low[2].z -= 0.12;
    low[3].z -= 0.02;
    const std::vector<double> upper = {-0.30, -0.12, 0.06, std::numeric_limits<double>::infinity()};
    const double rise = measuredRise(low);
    std::vector<LineSegment> edges = low;
    ASSERT_TRUE(fitEdgesOnStartSurface(-0.5, upper, rise, edges));
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(edges[k].z, -0.5 + (k + 1) * 0.18, 0.01) << k;

    // The first edge a rise above the start: it is a nosing, nothing moves.
    std::vector<LineSegment> level = straightEdges(4.0, -0.32, 0.18, 0.3, 4);
    EXPECT_FALSE(fitEdgesOnStartSurface(-0.5, upper, 0.18, level));
    EXPECT_EQ(level[0].z, -0.32);
    // No upper bound at all, or bounds no line from the start fits, or too loose: unchanged.
    const double inf = std::numeric_limits<double>::infinity();
    edges = low;
    EXPECT_FALSE(fitEdgesOnStartSurface(-0.5, {inf, inf, inf, inf}, rise, edges));
    EXPECT_FALSE(fitEdgesOnStartSurface(-0.5, {-0.30, -0.25, 0.06, inf}, rise, edges));
    EXPECT_FALSE(fitEdgesOnStartSurface(-0.5, {0.5, inf, inf, inf}, rise, edges));
    for (int k = 0; k < 4; ++k) EXPECT_EQ(edges[k].z, low[k].z);
    EXPECT_FALSE(fitEdgesOnStartSurface(-0.5, {-0.3}, rise, edges));  // sizes differ
    // A put-back edge (no points) is no lower bound: set high, it does not block the fit.
    edges = low;
    edges[2].z = 0.2;
    edges[2].num_points = 0;
    EXPECT_TRUE(fitEdgesOnStartSurface(-0.5, upper, rise, edges));
    EXPECT_NEAR(edges[2].z, 0.04, 0.01);
}

}  // namespace
}  // namespace stairmap
