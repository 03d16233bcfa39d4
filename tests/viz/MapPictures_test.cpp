// The map pictures: .3Dscene reloads with MRPT and holds the expected objects; overview.png shows
// the staircase in red where it is.
#include <gtest/gtest.h>

#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CText.h>

#include <filesystem>

#include "viz/MapOverview.h"
#include "viz/MapScene.h"

namespace stairmap::viz {
using map::VoxelMap;
namespace {

MapView smallView(const VoxelMap& voxels) {
    MapView view;
    view.voxels = &voxels;
    StaircaseLandmark lm;
    lm.id = 7;
    lm.stairs.step_height = 0.17;
    lm.stairs.step_depth = 0.28;
    for (int i = 0; i < 4; ++i) {
        StairEdge e;
        e.start = Eigen::Vector3d(2.0 + 0.28 * i, -0.6, 0.17 * (i + 1));
        e.end = Eigen::Vector3d(2.0 + 0.28 * i, 0.6, 0.17 * (i + 1));
        lm.stairs.steps.push_back(e);
    }
    lm.stairs.location = lm.stairs.steps[0].centre();
    view.staircases.push_back(lm);
    Floor f;
    f.id = 0;
    view.floors.push_back(f);
    view.trajectory = {{-2, 0, 0.35}, {0, 0, 0.35}, {1, 0, 0.35}};
    return view;
}

std::string scratch(const std::string& name) {
    const auto dir = std::filesystem::path(STAIRMAP_TEST_TMP) / "MapPictures";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

TEST(MapPictures, SceneReloadsWithStepBoxesAndLabel) {
    VoxelMap voxels;
    voxels.insertScan({{1, 1, 0}, {2, 1, 0}, {3, 1, 1}}, Eigen::Vector3d::Zero());
    const std::string path = scratch("scene.3Dscene");
    saveMapScene(smallView(voxels), path);
    mrpt::opengl::COpenGLScene scene;
    ASSERT_TRUE(scene.loadFromFile(path));
    int boxes = 0, labels = 0;
    for (const auto& obj : *scene.getViewport()) {
        if (std::dynamic_pointer_cast<mrpt::opengl::CBox>(obj)) ++boxes;
        if (auto t = std::dynamic_pointer_cast<mrpt::opengl::CText>(obj)) {
            ++labels;
            EXPECT_NE(t->getString().find("7"), std::string::npos);
        }
    }
    EXPECT_EQ(boxes, 4);
    EXPECT_EQ(labels, 1);
}

TEST(MapPictures, OverviewShowsTheStaircaseInRed) {
    VoxelMap voxels;
    voxels.insertScan({{-2, -2, 0}, {4, 2, 0}, {4, 2, 2}}, Eigen::Vector3d::Zero());
    const std::string path = scratch("overview.png");
    OverviewParams params;
    saveMapOverview(smallView(voxels), path, params);
    mrpt::img::CImage img;
    ASSERT_TRUE(img.loadFromFile(path));
    EXPECT_EQ(img.getWidth(), 2u * params.panel_px);  // one floor + the side view
    int red = 0;
    for (unsigned y = 0; y < img.getHeight(); ++y) {
        for (unsigned x = 0; x < img.getWidth() / 2; ++x) {
            const uint8_t* px = img(x, y);  // BGR
            red += px[2] > 180 && px[1] < 80 && px[0] < 80;
        }
    }
    EXPECT_GT(red, 100);  // 4 edges x ~1.2 m at ~70 px/m, 2 px wide, plus the label
}

// Coordinates so far apart that the extent overflows to infinity: the pixel arithmetic once
// overflowed int (UBSan: signed overflow in MapOverview.cpp). The near staircase must still be
// drawn (the far points squeeze it into a few pixels, so only its presence is checked).
TEST(MapPictures, OverviewSurvivesFarAndNonFiniteExtents) {
    VoxelMap voxels;
    voxels.insertScan({{-2, -2, 0}, {4, 2, 0}}, Eigen::Vector3d::Zero());
    MapView view = smallView(voxels);
    view.trajectory.push_back({1.5e308, -1.5e308, 1e308});
    view.trajectory.push_back({-1.5e308, 1.5e308, -1e308});
    const std::string path = scratch("overview_far.png");
    ASSERT_NO_THROW(saveMapOverview(view, path, OverviewParams{}));
    mrpt::img::CImage img;
    ASSERT_TRUE(img.loadFromFile(path));
    EXPECT_EQ(img.getWidth(), 2u * OverviewParams{}.panel_px);
}

}  // namespace
}  // namespace stairmap::viz
