#include "viz/ViewerCamera.h"

#include <algorithm>
#include <cmath>

namespace stairmap::viz {

std::optional<CameraMode> parseCameraMode(const std::string& name) {
    if (name == "follow") return CameraMode::Follow;
    if (name == "top") return CameraMode::Top;
    if (name == "orbit") return CameraMode::Orbit;
    return std::nullopt;
}

const char* cameraModeName(CameraMode mode) {
    switch (mode) {
        case CameraMode::Follow: return "follow";
        case CameraMode::Top: return "top";
        case CameraMode::Orbit: return "orbit";
    }
    return "?";
}

CameraView cameraFor(CameraMode mode, const std::optional<Eigen::Isometry3d>& T_world_robot,
                     const SceneBounds& bounds, double orbit_azimuth_deg) {
    CameraView v;
    const Eigen::Vector3d size = bounds.max - bounds.min;
    const double extent = std::max({size.x(), size.y(), 4.0});
    const double tan_half_fov = std::tan(30.0 * M_PI / 180.0);  // 60 deg vertical FOV
    constexpr double kAspect = 16.0 / 9.0;  // the default window / frame shape
    if (mode == CameraMode::Follow && T_world_robot) {
        const Eigen::Vector3d x = T_world_robot->linear().col(0);
        const double yaw_deg = std::atan2(x.y(), x.x()) * 180.0 / M_PI;
        v.target = T_world_robot->translation();
        v.distance_m = 9.0;
        v.azimuth_deg = yaw_deg + 180.0;  // the eye sits behind the robot ...
        v.elevation_deg = 55.0;           // ... high enough to look over nearby walls
        return v;
    }
    v.target = bounds.centre();
    if (mode == CameraMode::Top) {
        // Fit y in the picture's height and x in its width (+10 %).
        v.distance_m = 1.1 * std::max({size.y(), size.x() / kAspect, 4.0}) / (2.0 * tan_half_fov);
        v.azimuth_deg = -90.0;  // +y up in the picture
        v.elevation_deg = 89.5;
        return v;
    }
    v.distance_m = 0.9 * extent;
    v.azimuth_deg = orbit_azimuth_deg;
    v.elevation_deg = 40.0;
    return v;
}

}  // namespace stairmap::viz
