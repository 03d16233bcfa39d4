// core/TreadBoundaries: nosings read between flat top-surface patches a rise apart, on surfaces
// built from known treads (a spiral's wedges, a straight flight). Truth comes from the
// construction, never from the code under test.

#include "core/TreadBoundaries.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/HeightGrid.h"

namespace stairmap {
namespace {

constexpr double kDeg = M_PI / 180.0;

/// An elevation map's cloud: one point per `spacing` on the top surface height(x, y) over the
/// square `centre` +- half; height returns NaN where nothing is seen.
PointCloud topSurfaceCloud(const std::function<double(double, double)>& height,
                           const Eigen::Vector2d& centre, double half, double spacing = 0.02) {
    PointCloud cloud;
    for (double x = centre.x() - half; x < centre.x() + half; x += spacing)
        for (double y = centre.y() - half; y < centre.y() + half; y += spacing) {
            const double z = height(x, y);
            if (std::isfinite(z)) cloud.emplace_back(x, y, z);
        }
    return cloud;
}

/// A spiral's five wedge treads about `axis` (nosing k = 1..5 at angle (k - 1) step, height
/// k rise), the floor at 0 around them, the column unseen.
struct Wedges {
    Eigen::Vector2d axis{2.0, 0.5};
    double inner = 0.15, outer = 1.0, rise = 0.17, step = 32.0 * kDeg;
    int levels = 5;
    double height(double x, double y) const {
        const Eigen::Vector2d d = Eigen::Vector2d(x, y) - axis;
        const double r = d.norm();
        if (r < inner) return std::nan("");
        double a = std::atan2(d.y(), d.x());
        if (a < 0) a += 2 * M_PI;
        const int k = static_cast<int>(a / step);
        if (r > outer || k >= levels) return 0.0;
        return (k + 1) * rise;
    }
};

HeightGrid gridOf(const PointCloud& cloud, const Eigen::Vector2d& centre) {
    HeightGrid g;
    g.fill(cloud, centre, 2.0, 0.05, -0.05, 3.0);
    return g;
}

/// Lines at height z (within 1 cm) lying along the ray from `from` at angle `phi` (within 6 deg
/// and 5 cm) and reaching over at least `min_length` of it.
int linesAlong(const std::vector<LineSegment>& lines, const Eigen::Vector2d& from, double phi,
               double z, double min_length) {
    const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), side(-u.y(), u.x());
    int n = 0;
    for (const LineSegment& l : lines) {
        const Eigen::Vector2d d = (l.end - l.start).normalized();
        const bool along = std::abs(d.dot(u)) > std::cos(6.0 * kDeg);
        const bool on = std::abs((l.start - from).dot(side)) < 0.05 &&
                        std::abs((l.end - from).dot(side)) < 0.05;
        n += std::abs(l.z - z) < 0.01 && along && on && l.length() >= min_length;
    }
    return n;
}

TEST(TreadBoundaries, ReadsEveryWedgeNosingOfASpiralFromItsTreads) {
    const Wedges w;
    const PointCloud cloud =
        topSurfaceCloud([&](double x, double y) { return w.height(x, y); }, w.axis, 1.8);
    TreadBoundaryParams p;
    p.floor_z = 0.0;
    const auto lines = treadBoundaryNosings(gridOf(cloud, w.axis), p);
    // Nosing k: the boundary of wedge k over wedge k - 1 (the floor for k = 1), radial at its angle
    // from the column to the rim.
    for (int k = 1; k <= w.levels; ++k)
        EXPECT_EQ(linesAlong(lines, w.axis, (k - 1) * w.step, k * w.rise, 0.6), 1) << k;
    // Besides them only the first wedge's rim over the floor: the higher rims stand more than a
    // rise over it.
    EXPECT_LE(lines.size(), static_cast<std::size_t>(w.levels + 1));
}

TEST(TreadBoundaries, ReadsTheParallelNosingsOfAStraightFlight) {
    // Four steps of 0.15 m rise and 0.30 m run rising along +x from x = 1.0, 1.2 m wide.
    const auto height = [](double x, double y) -> double {
        if (std::abs(y) > 0.6 || x < 1.0) return 0.0;
        return 0.15 * std::min(4, 1 + static_cast<int>((x - 1.0) / 0.3));
    };
    const PointCloud cloud = topSurfaceCloud(height, {1.8, 0.0}, 1.5);
    TreadBoundaryParams p;
    const auto lines = treadBoundaryNosings(gridOf(cloud, {1.8, 0.0}), p);
    for (int k = 1; k <= 4; ++k)
        EXPECT_EQ(linesAlong(lines, {1.0 + 0.3 * (k - 1), -0.6}, M_PI / 2, 0.15 * k, 1.0), 1) << k;
}

TEST(TreadBoundaries, ANoisyRampBetweenTwoTreadsDoesNotJoinThem) {
    // The floor at 0 m and a tread at 0.15 m from x = 1.5 m; over part of the nosing (y < -0.2 m)
    // a depth camera's noise ramp of 2.5 cm per 5 cm cell leads up to it, each cell within
    // max_neighbour_dz_m of the next.
    const auto height = [](double x, double y) -> double {
        if (std::abs(y) > 0.5) return std::nan("");
        if (x >= 1.5) return 0.15;
        if (y < -0.2 && x >= 1.25) return 0.025 * (1 + std::floor((x - 1.25) / 0.05));
        return 0.0;
    };
    const PointCloud cloud = topSurfaceCloud(height, {1.5, 0.0}, 0.9);
    TreadBoundaryParams p;
    p.floor_band_m = 0.0;  // the floor grown like the tread
    EXPECT_EQ(linesAlong(treadBoundaryNosings(gridOf(cloud, {1.5, 0.0}), p), {1.5, -0.2}, M_PI / 2,
                         0.15, 0.6),
              1);
    // Grown by the neighbour step alone, the ramp joins the tread and the floor: no nosing.
    p.max_patch_dz_m = 1.0;
    p.max_patch_spread_m = 1.0;
    EXPECT_TRUE(treadBoundaryNosings(gridOf(cloud, {1.5, 0.0}), p).empty());
}

TEST(TreadBoundaries, NothingOnAFlatFloorOrAnEmptySurface) {
    TreadBoundaryParams p;
    const PointCloud floor = topSurfaceCloud(
        [](double x, double y) { return 0.01 * std::sin(7 * x) * std::cos(5 * y); }, {2, 0}, 1.9);
    EXPECT_TRUE(treadBoundaryNosings(gridOf(floor, {2, 0}), p).empty());
    EXPECT_TRUE(treadBoundaryNosings(gridOf({}, {2, 0}), p).empty());
    EXPECT_TRUE(treadBoundaryNosings(HeightGrid{}, p).empty());
}

TEST(HeightGrid, KeepsEachCellsHighestPointAndIgnoresTheRest) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const PointCloud cloud = {
        {1.01f, 1.01f, 0.10f}, {1.04f, 1.02f, 0.30f}, {1.03f, 1.03f, 0.20f},  // one cell: 0.30
        {1.01f, 1.01f, 5.0f},                                                 // above z_hi
        {nan, 1.0f, 0.5f},     {1.0f, inf, 0.5f},     {1.0f, 1.0f, nan},      // not finite
        {9.0f, 9.0f, 0.1f},                                                   // outside
    };
    HeightGrid g;
    g.fill(cloud, {1.0, 1.0}, 0.5, 0.05, -0.1, 3.0);
    EXPECT_EQ(g.n, 22);  // 20 cells and the border
    int occupied = 0;
    for (int i = 0; i < static_cast<int>(g.top.size()); ++i) {
        if (g.top[i] == HeightGrid::kEmpty) continue;
        ++occupied;
        EXPECT_FLOAT_EQ(g.top[i], 0.30f);
        EXPECT_LT((g.centre(i) - Eigen::Vector2d(1.025, 1.025)).norm(), 1e-9);
    }
    EXPECT_EQ(occupied, 1);
    for (int k = 0; k < g.n; ++k) {  // the border stays empty
        EXPECT_EQ(g.top[k], HeightGrid::kEmpty);
        EXPECT_EQ(g.top[static_cast<std::size_t>(g.n - 1) * g.n + k], HeightGrid::kEmpty);
    }
}

}  // namespace
}  // namespace stairmap
