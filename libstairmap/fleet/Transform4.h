#pragma once
// A gravity-aligned rigid transform with 4 degrees of freedom (x, y, z, yaw): what separates two
// robots' map frames when both know "up" (IMU / legged odometry), so roll and pitch are zero.

#include <cmath>

#include <Eigen/Geometry>

namespace stairmap::fleet {

/// T_to_from: p_to = Rz(yaw_rad) * p_from + (x, y, z).
struct Transform4 {
    double x = 0.0;        ///< [m]
    double y = 0.0;        ///< [m]
    double z = 0.0;        ///< [m]
    double yaw_rad = 0.0;  ///< [rad] counter-clockwise about +z

    Eigen::Isometry3d isometry() const {
        Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
        T.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        T.translation() = Eigen::Vector3d(x, y, z);
        return T;
    }
    Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return isometry() * p; }
};

/// Angle wrapped into (-pi, pi].
inline double wrapAngle(double a) {
    a = std::remainder(a, 2.0 * M_PI);
    return a <= -M_PI ? a + 2.0 * M_PI : a;
}

}  // namespace stairmap::fleet
