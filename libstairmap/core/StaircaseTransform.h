#pragma once
// Moving a staircase between frames (e.g. robot -> world with T_world_robot).

#include <Eigen/Geometry>

#include "core/Staircase.h"

namespace stairmap {

/// Returns `stairs` expressed in frame "to": edge end points p_to = T_to_from * p_from, location and
/// heading follow, and each edge's (rho, theta) covariance is propagated to first order through the
/// planar part of the transform (yaw + XY translation; both frames are assumed gravity-aligned, a
/// residual roll/pitch only moves the points). step_height/depth/width and slope are invariant and
/// copied. Cost O(k).
Staircase transformStaircase(const Staircase& stairs, const Eigen::Isometry3d& T_to_from);

/// First-order propagation of a (rho, theta) covariance of a line through a planar rigid motion
/// (yaw [rad], translation t [m]). `rho_theta_from` is the line in the source frame (rho >= 0).
Eigen::Matrix2d transformLineCovariance(const Eigen::Matrix2d& cov_from,
                                        const Eigen::Vector2d& rho_theta_from, double yaw,
                                        const Eigen::Vector2d& t);

}  // namespace stairmap
