#include "viz/ViewerScene.h"

#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/opengl/COpenGLViewport.h>
#include <mrpt/img/color_maps.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>

namespace stairmap::viz {
namespace {

using mrpt::opengl::CPointCloudColoured;

/// [m] the robot's floor band for the voxel filter, relative to its floor
constexpr double kFloorBandBelowM = 0.3;
constexpr double kFloorBandAboveM = 2.2;

/// Points coloured by height with `map` over [z_lo, z_hi] (clamped outside).
CPointCloudColoured::Ptr heightCloud(const PointCloud& points, double z_lo, double z_hi,
                                     mrpt::img::TColormap map, float point_size) {
    auto cloud = CPointCloudColoured::Create();
    cloud->setPointSize(point_size);
    cloud->reserve(points.size());
    const double span = std::max(z_hi - z_lo, 1e-3);
    for (const auto& p : points) {
        const float t = static_cast<float>(std::clamp((p.z() - z_lo) / span, 0.0, 1.0));
        float r, g, b;
        mrpt::img::colormap(map, t, r, g, b);
        cloud->push_back(p.x(), p.y(), p.z(), r, g, b);
    }
    return cloud;
}

/// The robot's floor height [m], or the lowest floor when the robot is unknown.
double robotFloorZ(const ViewFrame& f) {
    if (f.T_world_robot) return f.T_world_robot->translation().z() - f.robot_height_m;
    return f.floors.empty() ? 0.0 : f.floors.front().z;
}

void addScan(const ViewFrame& f, mrpt::opengl::COpenGLScene& scene) {
    if (f.scan_robot == nullptr || !f.T_world_robot) return;
    const Eigen::Isometry3f T = f.T_world_robot->cast<float>();
    PointCloud world;
    world.reserve(f.scan_robot->size());
    for (const auto& p : *f.scan_robot) world.push_back(T * p);
    const double floor_z = robotFloorZ(f);
    scene.insert(heightCloud(world, floor_z - 1.0, floor_z + 3.0, mrpt::img::cmHOT, 2.5f));
}

void addVoxels(const ViewFrame& f, bool robot_floor_only, mrpt::opengl::COpenGLScene& scene) {
    if (f.voxels == nullptr) return;
    PointCloud centres = f.voxels->occupiedVoxelCentres();
    double lo = 1e9, hi = -1e9;
    for (const auto& c : centres) lo = std::min<double>(lo, c.z()), hi = std::max<double>(hi, c.z());
    if (robot_floor_only) {
        const double floor_z = robotFloorZ(f);
        lo = floor_z - kFloorBandBelowM;
        hi = floor_z + kFloorBandAboveM;
        centres.erase(std::remove_if(centres.begin(), centres.end(),
                                     [&](const Eigen::Vector3f& c) { return c.z() < lo || c.z() > hi; }),
                      centres.end());
    }
    scene.insert(heightCloud(centres, lo, hi, mrpt::img::cmJET, 1.5f));
}

/// A floor level as a 1 m grid of lines at its height: a "plane" that never hides what lies
/// below it (MRPT sorts translucent triangles by shader, not depth, so a translucent quad did).
void addFloors(const ViewFrame& f, const SceneBounds& b, mrpt::opengl::COpenGLScene& scene) {
    for (const Floor& floor : f.floors) {
        auto grid = mrpt::opengl::CGridPlaneXY::Create(b.min.x(), b.max.x(), b.min.y(), b.max.y(),
                                                       floor.z, 1.0);
        grid->setColor_u8(120, 160, 255, 140);
        scene.insert(grid);
    }
}

/// The robot as unlit lines (shading made solids too dark to spot): a white footprint with a red
/// arrow along its heading and a white post up to 1 m above it.
mrpt::opengl::CSetOfObjects::Ptr robotMarker(const Eigen::Isometry3d& T_world_robot) {
    auto robot = mrpt::opengl::CSetOfObjects::Create();
    auto body = mrpt::opengl::CSetOfLines::Create();
    const double x = 0.35, y = 0.22, z = 0.0;
    body->appendLine(-x, -y, z, x, -y, z);
    body->appendLine(x, -y, z, x, y, z);
    body->appendLine(x, y, z, -x, y, z);
    body->appendLine(-x, y, z, -x, -y, z);
    body->appendLine(0, 0, z, 0, 0, z + 1.0);
    body->setLineWidth(4.0f);
    body->setColor_u8(255, 255, 255);
    robot->insert(body);
    auto arrow = mrpt::opengl::CSetOfLines::Create();
    arrow->appendLine(0, 0, z, 0.9, 0, z);
    arrow->appendLine(0.9, 0, z, 0.65, 0.18, z);
    arrow->appendLine(0.9, 0, z, 0.65, -0.18, z);
    arrow->setLineWidth(5.0f);
    arrow->setColor_u8(255, 40, 40);
    robot->insert(arrow);
    robot->setPose(mrptPose(T_world_robot));
    return robot;
}

void addTrajectory(const ViewFrame& f, mrpt::opengl::COpenGLScene& scene) {
    auto lines = mrpt::opengl::CSetOfLines::Create();
    for (std::size_t i = 1; i < f.trajectory.size(); ++i) {
        const auto& a = f.trajectory[i - 1];
        const auto& b = f.trajectory[i];
        lines->appendLine(a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
    }
    lines->setLineWidth(2.0f);
    lines->setColor_u8(80, 140, 255);
    scene.insert(lines);
    if (f.T_world_robot) scene.insert(robotMarker(*f.T_world_robot));
}

void grow(SceneBounds& b, bool& any, const Eigen::Vector3d& p) {
    b.min = any ? b.min.cwiseMin(p) : p;
    b.max = any ? b.max.cwiseMax(p) : p;
    any = true;
}

}  // namespace

mrpt::poses::CPose3D mrptPose(const Eigen::Isometry3d& T) {
    return mrpt::poses::CPose3D(mrpt::math::CMatrixDouble44(T.matrix()));
}

SceneBounds frameBounds(const ViewFrame& f) {
    SceneBounds b;
    bool any = false;
    for (const auto& p : f.trajectory) grow(b, any, p);
    for (const auto& l : f.landmarks)
        for (const auto& e : l.stairs.steps) grow(b, any, e.start), grow(b, any, e.end);
    if (f.T_world_robot) grow(b, any, f.T_world_robot->translation());
    if (!any && f.voxels != nullptr)
        for (const auto& c : f.voxels->occupiedVoxelCentres()) grow(b, any, c.cast<double>());
    if (!any) return SceneBounds{};
    b.min -= Eigen::Vector3d(2.0, 2.0, 0.5);  // margin: walls just beyond the path
    b.max += Eigen::Vector3d(2.0, 2.0, 0.5);
    return b;
}

void buildViewerScene(const ViewFrame& f, const ViewLayers& layers,
                      mrpt::opengl::COpenGLScene& scene) {
    scene.clear();
    scene.getViewport()->setCustomBackgroundColor(mrpt::img::TColorf(0.12f, 0.12f, 0.14f));
    const SceneBounds bounds = frameBounds(f);
    if (f.floors.empty() || !layers.floors) {  // a neutral ground grid when no floor is drawn
        auto grid = mrpt::opengl::CGridPlaneXY::Create(bounds.min.x(), bounds.max.x(),
                                                       bounds.min.y(), bounds.max.y(), 0.0, 1.0);
        grid->setColor_u8(90, 90, 90, 120);
        scene.insert(grid);
    }
    if (layers.voxels) addVoxels(f, layers.voxels_robot_floor, scene);
    if (layers.scan) addScan(f, scene);
    if (layers.floors) addFloors(f, bounds, scene);
    if (layers.trajectory) addTrajectory(f, scene);
    if (f.run && (layers.detector || layers.submap))
        scene.insert(detectorObjects(*f.run, layers.detector, layers.submap));
    if (layers.landmarks) scene.insert(landmarkObjects(f.landmarks, f.selected_id));
}

}  // namespace stairmap::viz
