#include "map/VoxelMap.h"

#include <gtest/gtest.h>

#include <octomap/OcTree.h>

#include <filesystem>
#include <limits>
#include <sstream>

namespace stairmap::map {
namespace {

std::string scratchDir(const std::string& name) {
    const auto dir = std::filesystem::path(STAIRMAP_TEST_TMP) / ("VoxelMap_" + name);
    std::filesystem::create_directories(dir);
    return dir.string();
}

// Three points in distinct 10 cm voxels plus one far away and one NaN.
PointCloud knownPoints() {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    return {{1.02f, 0.03f, 0.04f}, {1.02f, 0.04f, 0.05f},  // same voxel twice
            {2.05f, -1.05f, 0.55f}, {-0.55f, 0.45f, 1.25f}, {50.f, 0.f, 0.f}, {nan, 0.f, 0.f}};
}

TEST(VoxelMap, EndpointInsertionMarksHitVoxelsOnly) {
    VoxelMapParams params;
    params.resolution_m = 0.1;
    params.max_range_m = 10.0;
    VoxelMap map(params);
    EXPECT_EQ(map.insertScan(knownPoints(), Eigen::Vector3d::Zero()), 4u);  // far + NaN dropped
    EXPECT_TRUE(map.isOccupied({1.05, 0.05, 0.05}));
    EXPECT_TRUE(map.isOccupied({2.05, -1.05, 0.55}));
    EXPECT_TRUE(map.isOccupied({-0.55, 0.45, 1.25}));
    EXPECT_FALSE(map.isOccupied({50.0, 0.0, 0.0}));
    EXPECT_FALSE(map.isOccupied({0.5, 0.0, 0.0}));  // on the ray, but endpoints mode
    EXPECT_EQ(map.occupiedVoxelCentres().size(), 3u);
    EXPECT_GT(map.memoryUsageBytes(), 0u);
}

TEST(VoxelMap, RayCastingAlsoMarksFreeSpace) {
    VoxelMapParams params;
    params.resolution_m = 0.1;
    params.insertion_mode = VoxelInsertionMode::RayCast;
    VoxelMap map(params);
    map.insertScan({{2.05f, 0.05f, 0.05f}}, Eigen::Vector3d(0.05, 0.05, 0.05));
    EXPECT_TRUE(map.isOccupied({2.05, 0.05, 0.05}));
    EXPECT_FALSE(map.isOccupied({1.05, 0.05, 0.05}));
    EXPECT_GT(map.numLeaves(), 10u);  // free voxels along the ray are known
}

TEST(VoxelMap, SavedBtFileReadsBackWithOctomap) {
    VoxelMapParams params;
    params.resolution_m = 0.1;
    VoxelMap map(params);
    map.insertScan(knownPoints(), Eigen::Vector3d::Zero());
    const std::string path = scratchDir("save") + "/map.bt";
    map.save(path);

    octomap::OcTree tree(0.5);  // wrong resolution on purpose: the file carries its own
    ASSERT_TRUE(tree.readBinary(path));
    EXPECT_DOUBLE_EQ(tree.getResolution(), 0.1);
    const octomap::OcTreeNode* node = tree.search(2.05, -1.05, 0.55);
    ASSERT_NE(node, nullptr);
    EXPECT_TRUE(tree.isNodeOccupied(node));
    EXPECT_EQ(tree.search(0.5, 0.0, 0.0), nullptr);

    const VoxelMap loaded = VoxelMap::load(path);
    EXPECT_DOUBLE_EQ(loaded.resolution(), 0.1);
    EXPECT_TRUE(loaded.isOccupied({-0.55, 0.45, 1.25}));
    EXPECT_EQ(loaded.occupiedVoxelCentres().size(), 3u);
}

TEST(VoxelMap, EmptyScanIsNormal) {
    VoxelMap map;
    EXPECT_EQ(map.insertScan({}, Eigen::Vector3d::Zero()), 0u);
    EXPECT_EQ(map.numLeaves(), 0u);
    EXPECT_TRUE(map.occupiedVoxelCentres().empty());
}

TEST(VoxelMap, CorruptInputNamesTheSource) {
    std::istringstream garbage("this is not an octree");
    try {
        VoxelMap::readBinary(garbage, "garbage.bt");
        FAIL() << "expected an exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("garbage.bt"), std::string::npos) << e.what();
    }
    EXPECT_THROW(VoxelMap::load(scratchDir("missing") + "/nope.bt"), std::runtime_error);
}

TEST(VoxelMap, InvalidParamsThrow) {
    VoxelMapParams params;
    params.resolution_m = 0.0;
    EXPECT_THROW(VoxelMap{params}, std::invalid_argument);
}

}  // namespace
}  // namespace stairmap::map
