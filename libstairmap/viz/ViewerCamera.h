#pragma once
// Where the viewer's camera looks from: the same three modes in the window and headless.
// A CameraView is an orbit camera (target point, distance, azimuth, elevation), the model both
// mrpt::opengl::CCamera and the window's canvas use.

#include <Eigen/Geometry>
#include <optional>
#include <string>

namespace stairmap::viz {

enum class CameraMode { Follow, Top, Orbit };

/// "follow", "top", "orbit" -> mode; std::nullopt for anything else.
std::optional<CameraMode> parseCameraMode(const std::string& name);
const char* cameraModeName(CameraMode mode);

struct CameraView {
    Eigen::Vector3d target = Eigen::Vector3d::Zero();  ///< [m] world point looked at
    double distance_m = 10.0;                          ///< [m] eye to target
    double azimuth_deg = 0.0;    ///< [deg] eye direction seen from the target, CCW from +x
    double elevation_deg = 30.0; ///< [deg] above the horizontal
};

/// Axis-aligned bounds of what is drawn [m] (used by the top and orbit views).
struct SceneBounds {
    Eigen::Vector3d min = Eigen::Vector3d::Constant(-5.0);
    Eigen::Vector3d max = Eigen::Vector3d::Constant(5.0);
    Eigen::Vector3d centre() const { return 0.5 * (min + max); }
};

/// Follow: behind and above the robot, looking along its heading (8 m, 35 deg).
/// Top: straight down on the bounds' centre, far enough to see them whole.
/// Orbit: around the bounds' centre at `orbit_azimuth_deg`, 40 deg up.
/// Without a robot pose, Follow behaves as Orbit.
CameraView cameraFor(CameraMode mode, const std::optional<Eigen::Isometry3d>& T_world_robot,
                     const SceneBounds& bounds, double orbit_azimuth_deg);

}  // namespace stairmap::viz
