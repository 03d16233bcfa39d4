#pragma once
// What `stairmap view` draws for one moment of a replay, as MRPT OpenGL objects (world frame):
// the current scan and the voxel map coloured by height, the detection submap box, the detector's
// internals, landmarks (step edges, treads, ID labels; confirmed and tentative in different
// colours), floors as translucent planes, the trajectory and the robot. The same scene goes to the
// window and to the headless renderer.

#include <Eigen/Geometry>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/poses/CPose3D.h>
#include <optional>
#include <vector>

#include "core/DetectorDebug.h"
#include "map/LandmarkTypes.h"
#include "map/VoxelMap.h"
#include "viz/ViewerCamera.h"

namespace stairmap::viz {

/// Layer switches (the window's checkboxes / keys).
struct ViewLayers {
    bool scan = true;                ///< current scan, coloured by height
    bool voxels = true;              ///< voxel map leaves, coloured by height
    bool voxels_robot_floor = true;  ///< only the leaves of the robot's floor (-0.3 .. +2.2 m)
    bool submap = true;              ///< detection submap box
    bool detector = true;            ///< candidates, row lines, accepted / rejected chains
    bool landmarks = true;           ///< landmark step edges, treads and IDs
    bool floors = true;              ///< a translucent plane per floor level
    bool trajectory = true;          ///< robot path and the robot itself
};

inline bool operator==(const ViewLayers& a, const ViewLayers& b) {
    return a.scan == b.scan && a.voxels == b.voxels && a.voxels_robot_floor == b.voxels_robot_floor &&
           a.submap == b.submap && a.detector == b.detector && a.landmarks == b.landmarks &&
           a.floors == b.floors && a.trajectory == b.trajectory;
}
inline bool operator!=(const ViewLayers& a, const ViewLayers& b) { return !(a == b); }

/// The latest detector run: its frame and debug record (grav frame) and detections (world).
struct DetectorView {
    Eigen::Isometry3d T_world_grav = Eigen::Isometry3d::Identity();
    double radius_m = 0.0;                 ///< [m] submap radius
    const DetectorDebug* debug = nullptr;  ///< may be null (no internals drawn)
    std::vector<Staircase> detections_world;
};

/// One moment of a replay or a finished map (world frame; pointers may be null).
struct ViewFrame {
    const map::VoxelMap* voxels = nullptr;
    const PointCloud* scan_robot = nullptr;               ///< robot frame
    std::optional<Eigen::Isometry3d> T_world_robot;       ///< the robot now, if known
    std::vector<StaircaseLandmark> landmarks;
    std::vector<Floor> floors;
    std::vector<Eigen::Vector3d> trajectory;              ///< [m] robot positions in order
    std::optional<DetectorView> run;
    double robot_height_m = 0.35;  ///< [m] robot frame above its floor (robot's floor filter)
    int selected_id = -1;          ///< highlighted landmark, -1 = none
};

/// An Eigen rigid transform as an MRPT pose.
mrpt::poses::CPose3D mrptPose(const Eigen::Isometry3d& T);

/// Landmark colours (RGB): the end-to-end test looks for them in screenshots.
constexpr unsigned char kConfirmedRgb[3] = {30, 220, 60};
constexpr unsigned char kTentativeRgb[3] = {255, 150, 0};

/// Builds the frame's objects into `scene` (cleared first; background dark grey).
void buildViewerScene(const ViewFrame& frame, const ViewLayers& layers,
                      mrpt::opengl::COpenGLScene& scene);

/// Bounds of the frame's content (voxels, trajectory, landmarks) for the top and orbit cameras.
SceneBounds frameBounds(const ViewFrame& frame);

/// Detector internals and the submap box (in the grav frame, placed at T_world_grav).
mrpt::opengl::CSetOfObjects::Ptr detectorObjects(const DetectorView& run, bool internals,
                                                 bool box);
/// Step edges, treads and the ID label of each landmark; `selected_id` drawn highlighted.
mrpt::opengl::CSetOfObjects::Ptr landmarkObjects(const std::vector<StaircaseLandmark>& landmarks,
                                                 int selected_id);

}  // namespace stairmap::viz
