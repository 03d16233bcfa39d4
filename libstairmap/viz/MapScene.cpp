#include "viz/MapScene.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CText.h>
#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include <stdexcept>

namespace stairmap::viz {
using map::VoxelMap;
namespace {

mrpt::opengl::CPointCloud::Ptr voxelCloud(const VoxelMap& voxels) {
    auto cloud = mrpt::opengl::CPointCloud::Create();
    for (const auto& c : voxels.occupiedVoxelCentres()) cloud->insertPoint(c.x(), c.y(), c.z());
    cloud->setPointSize(2.0f);
    cloud->enableColorFromZ(true);  // colour by height
    return cloud;
}

mrpt::opengl::CSetOfLines::Ptr trajectoryLines(const std::vector<Eigen::Vector3d>& trajectory) {
    auto lines = mrpt::opengl::CSetOfLines::Create();
    for (std::size_t i = 1; i < trajectory.size(); ++i) {
        const auto& a = trajectory[i - 1];
        const auto& b = trajectory[i];
        lines->appendLine(a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
    }
    lines->setLineWidth(2.0f);
    lines->setColor_u8(0, 0, 255);
    return lines;
}

/// One box per step: the tread behind each nosing edge (uphill), one rise deep.
void addStaircase(mrpt::opengl::COpenGLScene& scene, const StaircaseLandmark& landmark) {
    const Staircase& s = landmark.stairs;
    const double depth = s.step_depth > 0 ? s.step_depth : 0.25;
    const double rise = s.step_height > 0 ? s.step_height : 0.15;
    for (const StairEdge& edge : s.steps) {
        const double half_width = 0.5 * edge.length();
        auto box = mrpt::opengl::CBox::Create(mrpt::math::TPoint3D(0, -half_width, -rise),
                                              mrpt::math::TPoint3D(depth, half_width, 0));
        const Eigen::Vector3d c = edge.centre();
        box->setPose(mrpt::poses::CPose3D(c.x(), c.y(), c.z(), s.heading_rad, 0, 0));
        box->setColor_u8(landmark.confirmed ? 220 : 240, landmark.confirmed ? 60 : 170, 40, 200);
        scene.insert(box);
    }
    auto label = mrpt::opengl::CText::Create("stair #" + std::to_string(landmark.id));
    label->setLocation(s.location.x(), s.location.y(), s.location.z() + 0.8);
    label->setColor_u8(255, 0, 0);
    scene.insert(label);
}

}  // namespace

void saveMapScene(const MapView& view, const std::string& path) {
    mrpt::opengl::COpenGLScene scene;
    scene.insert(mrpt::opengl::CGridPlaneXY::Create(-50, 50, -50, 50, 0, 5));
    if (view.voxels != nullptr) scene.insert(voxelCloud(*view.voxels));
    if (view.trajectory.size() >= 2) scene.insert(trajectoryLines(view.trajectory));
    for (const auto& landmark : view.staircases) addStaircase(scene, landmark);
    try {
        mrpt::io::CFileGZOutputStream out;
        if (!out.open(path, 1)) throw std::runtime_error("cannot open for writing");
        auto archive = mrpt::serialization::archiveFrom(out);
        archive << scene;
    } catch (const std::exception& e) {
        throw std::runtime_error(path + ": writing the 3D scene failed: " + e.what());
    }
}

}  // namespace stairmap::viz
