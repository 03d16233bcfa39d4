// Floor rasterisation and stair masks on voxel scenes with known free, occupied and unseen areas.
#include "export/FloorGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "SyntheticLandmarks.h"
#include "export/StairMask.h"

namespace stairmap::exporting {
namespace {

Cell cellAt(const FloorGrid& g, double x, double y) {
    const auto c = g.cellOf(x, y);
    EXPECT_TRUE(c.has_value()) << x << ", " << y << " outside the grid";
    return c ? g.at(c->first, c->second) : Cell::Unknown;
}

/// Floor 0 (z = 0) over [0, 4] x [0, 3] with a hole at [2.5, 3] x [2, 2.5] that was never seen,
/// a 0.5 m box on it, a slab at 2.5 m (above any robot) and a floor 1 at z = 3 over [0, 2] x [0,
/// 3].
PointCloud scene() {
    PointCloud c;
    test::addFloorVoxels(c, 0.0, 2.5, 0.0, 3.0, 0.0);
    test::addFloorVoxels(c, 2.5, 4.0, 0.0, 2.0, 0.0);
    test::addFloorVoxels(c, 2.5, 3.0, 2.5, 3.0, 0.0);
    test::addFloorVoxels(c, 3.0, 4.0, 2.0, 3.0, 0.0);
    test::addBoxVoxels(c, {1.0, 1.0, 0.0}, {1.5, 1.5, 0.5});
    test::addFloorVoxels(c, 0.0, 4.0, 0.0, 3.0, 2.5);
    test::addFloorVoxels(c, 0.0, 2.0, 0.0, 3.0, 3.0);
    return c;
}

TEST(FloorGrid, FreeOccupiedUnknown) {
    FloorRasterParams p;
    p.robot_height_m = 0.7;
    const FloorGrid g = rasteriseFloor(scene(), 0.0, p);
    EXPECT_EQ(cellAt(g, 0.52, 0.52), Cell::Free);
    EXPECT_EQ(cellAt(g, 3.52, 0.52), Cell::Free);
    EXPECT_EQ(cellAt(g, 1.22, 1.22), Cell::Occupied);  // the box
    EXPECT_EQ(cellAt(g, 2.72, 2.22), Cell::Unknown);   // the hole
    EXPECT_EQ(cellAt(g, -0.22, 1.0), Cell::Unknown);   // the margin
    // The slab at 2.5 m is above the robot: nothing on floor 0 is blocked by it.
    int occupied = 0;
    for (Cell c : g.cells) occupied += c == Cell::Occupied;
    EXPECT_EQ(occupied, 100);  // 10 x 10 cells of the box
    const auto extent = freeExtent(g);
    ASSERT_TRUE(extent.has_value());
    EXPECT_NEAR((*extent)[0], 0.0, 0.051);
    EXPECT_NEAR((*extent)[1], 0.0, 0.051);
    EXPECT_NEAR((*extent)[2], 4.0, 0.051);
    EXPECT_NEAR((*extent)[3], 3.0, 0.051);
}

TEST(FloorGrid, TallRobotSeesTheSlabAndUpperFloorIsSeparate) {
    FloorRasterParams p;
    p.robot_height_m = 2.6;
    const FloorGrid low = rasteriseFloor(scene(), 0.0, p);
    EXPECT_EQ(cellAt(low, 3.52, 0.52), Cell::Occupied);
    p.robot_height_m = 0.4;
    const FloorGrid up = rasteriseFloor(scene(), 3.0, p);
    EXPECT_EQ(cellAt(up, 1.02, 1.02), Cell::Free);
    // Floor 1 spans x in [0, 2]; the grid ends a margin beyond it.
    EXPECT_FALSE(up.cellOf(3.5, 1.0).has_value());
}

TEST(FloorGrid, EmptyBandGivesEmptyGrid) {
    const FloorGrid g = rasteriseFloor(scene(), 10.0, FloorRasterParams{});
    EXPECT_EQ(g.width, 0);
    EXPECT_FALSE(freeExtent(g).has_value());
    FloorRasterParams bad;
    bad.resolution_m = 0.0;
    EXPECT_THROW(rasteriseFloor(scene(), 0.0, bad), std::invalid_argument);
}

/// Distance from p to the boundary of a convex polygon (corners in order).
double distanceToBoundary(const Eigen::Vector2d& p, const std::array<Eigen::Vector2d, 4>& poly) {
    double best = 1e9;
    for (int i = 0; i < 4; ++i) {
        const Eigen::Vector2d a = poly[i], b = poly[(i + 1) % 4];
        const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
        best = std::min(best, (a + t * (b - a) - p).norm());
    }
    return best;
}

bool insideConvex(const Eigen::Vector2d& p, const std::array<Eigen::Vector2d, 4>& poly) {
    for (int i = 0; i < 4; ++i) {
        const Eigen::Vector2d e = poly[(i + 1) % 4] - poly[i], d = p - poly[i];
        if (e.x() * d.y() - e.y() * d.x() < 0) return false;
    }
    return true;
}

TEST(StairMask, KnownFootprintsWithinOneCell) {
    PointCloud c;
    test::addFloorVoxels(c, -2.0, 10.0, -2.0, 10.0, 0.0);
    const FloorGrid floor = rasteriseFloor(c, 0.0, FloorRasterParams{});
    test::FlightSpec a;  // along +x from (2, 1): footprint x in [2, 2 + 9 * 0.28], y in [0.5, 1.5]
    a.foot = {2.0, 1.0, 0.0};
    test::FlightSpec b;  // rotated by 30 deg
    b.foot = {5.0, 5.0, 0.0};
    b.heading_rad = M_PI / 6;
    b.width = 1.4;
    const std::vector<FlightGeometry> flights = {measureFlight(test::makeLandmark(1, a, 0, 1)),
                                                 measureFlight(test::makeLandmark(2, b, 0, 1))};
    // Independent corners: foot +- half width across, top = foot + 9 runs along.
    const auto corners = [](const test::FlightSpec& f) {
        const Eigen::Vector2d u(std::cos(f.heading_rad), std::sin(f.heading_rad)), l(-u.y(), u.x());
        const Eigen::Vector2d foot = f.foot.head<2>(), top = foot + (f.risers - 1) * f.run * u;
        const double h = 0.5 * f.width;
        return std::array<Eigen::Vector2d, 4>{foot - h * l, top - h * l, top + h * l, foot + h * l};
    };
    const auto pa = corners(a), pb = corners(b);
    const FloorGrid mask = stairMask(floor, flights);
    int marked = 0, wrong = 0;
    for (int iy = 0; iy < mask.height; ++iy) {
        for (int ix = 0; ix < mask.width; ++ix) {
            const Eigen::Vector2d p = mask.cellCentre(ix, iy);
            const bool in = insideConvex(p, pa) || insideConvex(p, pb);
            const bool is = mask.at(ix, iy) == Cell::Occupied;
            marked += is;
            const double edge = std::min(distanceToBoundary(p, pa), distanceToBoundary(p, pb));
            if (in != is && edge > mask.resolution_m) ++wrong;
        }
    }
    EXPECT_EQ(wrong, 0);
    const double area = (2.52 * 1.0 + 2.52 * 1.4) / (0.05 * 0.05);
    EXPECT_NEAR(marked, area, 0.05 * area);
}

}  // namespace
}  // namespace stairmap::exporting
