// Floor maps and stair masks written in the map_server format and read back independently.
#include "io/export/MapServerFiles.h"

#include <gtest/gtest.h>
#include <mrpt/maps/COccupancyGridMap2D.h>

#include <filesystem>

#include "export/StairMask.h"
#include "export/SyntheticLandmarks.h"
#include "io/export/MapServerReader.h"

namespace stairmap::io {
namespace {

std::string scratch(const std::string& name) {
    const auto dir = std::filesystem::path(STAIRMAP_TEST_TMP) / "io_export" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

/// Floor at z = 1 over [-1.5, 3] x [0.5, 2.5] (a non-square area off the origin), with a pillar at
/// [2, 2.3] x [1, 1.3] and an unseen patch at [0, 0.5] x [1.5, 2.5].
PointCloud scene() {
    PointCloud c;
    test::addFloorVoxels(c, -1.5, 0.0, 0.5, 2.5, 1.0);
    test::addFloorVoxels(c, 0.0, 0.5, 0.5, 1.5, 1.0);
    test::addFloorVoxels(c, 0.5, 3.0, 0.5, 2.5, 1.0);
    test::addBoxVoxels(c, {2.0, 1.0, 1.0}, {2.3, 1.3, 2.0});
    return c;
}

TEST(MapServerFiles, FloorMapReadsBackWithWorldCoordinates) {
    const std::string dir = scratch("floor");
    const exporting::FloorGrid grid = exporting::rasteriseFloor(scene(), 1.0, {});
    saveMapServerMap(dir, "floor_3", grid);
    const test::MapServerMap m = test::readMapServerMap(dir + "/floor_3.yaml");
    EXPECT_EQ(m.yaml.at("image"), "floor_3.pgm");
    EXPECT_EQ(m.yaml.at("mode"), "trinary");
    EXPECT_EQ(m.yaml.at("negate"), "0");
    EXPECT_DOUBLE_EQ(m.resolution, 0.05);
    EXPECT_EQ(m.width, grid.width);
    EXPECT_EQ(m.height, grid.height);
    // Known places, by world coordinates through the reader's own geometry.
    EXPECT_EQ(m.occupancyAt(-1.0, 0.7), 0);
    EXPECT_EQ(m.occupancyAt(2.8, 2.3), 0);
    EXPECT_EQ(m.occupancyAt(2.15, 1.15), 100);
    EXPECT_EQ(m.occupancyAt(0.25, 2.0), -1);  // unseen patch
    EXPECT_EQ(m.occupancyAt(-1.8, 1.0), -1);  // margin
    EXPECT_EQ(m.occupancyAt(-2.2, 1.0), -2);  // beyond the margin
    // Every pillar cell and nothing else is occupied.
    int occupied = 0;
    for (unsigned char v : m.pixels) occupied += v == kPgmOccupied;
    EXPECT_EQ(occupied, 36);
}

TEST(MapServerFiles, StairMaskOnTheKnownFootprint) {
    const std::string dir = scratch("mask");
    PointCloud c;
    test::addFloorVoxels(c, -1.0, 8.0, -1.0, 8.0, 0.0);
    test::FlightSpec f;  // foot (1, 2), up +y, footprint x in [0.5, 1.5], y in [2, 2 + 9 * 0.28]
    f.foot = {1.0, 2.0, 0.0};
    f.heading_rad = M_PI / 2;
    const exporting::FloorGrid floor = exporting::rasteriseFloor(c, 0.0, {});
    saveMapServerMap(
        dir, "floor_0_stairs",
        exporting::stairMask(floor, {exporting::measureFlight(test::makeLandmark(1, f, 0, 1))}));
    const test::MapServerMap m = test::readMapServerMap(dir + "/floor_0_stairs.yaml");
    const double r = m.resolution, y_top = 2.0 + 9 * 0.28;
    int wrong = 0;
    for (double x = -0.9; x < 7.9; x += 0.5 * r) {
        for (double y = -0.9; y < 7.9; y += 0.5 * r) {
            const bool inside = x >= 0.5 && x <= 1.5 && y >= 2.0 && y <= y_top;
            const double edge = std::min(
                {std::abs(x - 0.5), std::abs(x - 1.5), std::abs(y - 2.0), std::abs(y - y_top)});
            const bool marked = m.occupancyAt(x, y) == 100;
            if (marked != inside && edge > r) ++wrong;
        }
    }
    EXPECT_EQ(wrong, 0);
}

TEST(MapServerFiles, MrptLoadsTheYaml) {
    // How an MRPT user reads a floor map: COccupancyGridMap2D::FromROSMapServerYAML. Its cells
    // hold the probability of being free (1 = free).
    const std::string dir = scratch("mrpt");
    saveMapServerMap(dir, "floor_0", exporting::rasteriseFloor(scene(), 1.0, {}));
    const auto grid = mrpt::maps::COccupancyGridMap2D::FromROSMapServerYAML(dir + "/floor_0.yaml");
    EXPECT_NEAR(grid.getResolution(), 0.05, 1e-6);
    EXPECT_NEAR(grid.getXMin(), -2.0, 0.051);
    EXPECT_GT(grid.getPos(-1.0, 0.7), 0.8);          // free
    EXPECT_LT(grid.getPos(2.15, 1.15), 0.2);         // the pillar
    EXPECT_NEAR(grid.getPos(0.25, 2.0), 0.5, 0.15);  // unseen
}

TEST(MapServerFiles, UnwritableDirectoryNamesTheFile) {
    const exporting::FloorGrid grid = exporting::rasteriseFloor(scene(), 1.0, {});
    try {
        saveMapServerMap("/nonexistent/dir", "floor_0", grid);
        FAIL() << "writing into a missing directory succeeded";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/floor_0.pgm"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace stairmap::io
