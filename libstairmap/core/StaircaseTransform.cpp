#include "core/StaircaseTransform.h"

#include <cmath>

namespace stairmap {

Eigen::Matrix2d transformLineCovariance(const Eigen::Matrix2d& cov_from,
                                        const Eigen::Vector2d& rho_theta_from, double yaw,
                                        const Eigen::Vector2d& t) {
    // theta' = theta + yaw;  rho' = rho + t . n(theta')   (n = unit normal)
    const double theta_to = rho_theta_from.y() + yaw;
    const Eigen::Vector2d dn(-std::sin(theta_to), std::cos(theta_to));  // d n / d theta
    Eigen::Matrix2d J;
    J << 1.0, t.dot(dn), 0.0, 1.0;
    Eigen::Matrix2d cov_to = J * cov_from * J.transpose();
    const double rho_to = rho_theta_from.x() + t.dot(Eigen::Vector2d(std::cos(theta_to),
                                                                     std::sin(theta_to)));
    if (rho_to < 0) {
        // Hessian form flips to (-rho', theta' + pi): d(-rho')/d(.) negates the cross terms.
        cov_to(0, 1) = -cov_to(0, 1);
        cov_to(1, 0) = -cov_to(1, 0);
    }
    return cov_to;
}

Staircase transformStaircase(const Staircase& stairs, const Eigen::Isometry3d& T_to_from) {
    const Eigen::Matrix3d R = T_to_from.rotation();
    const double yaw = std::atan2(R(1, 0), R(0, 0));
    const Eigen::Vector2d t = T_to_from.translation().head<2>();

    Staircase out = stairs;
    for (std::size_t i = 0; i < stairs.steps.size(); ++i) {
        const StairEdge& e = stairs.steps[i];
        StairEdge& o = out.steps[i];
        o.start = T_to_from * e.start;
        o.end = T_to_from * e.end;
        o.cov_rho_theta = transformLineCovariance(e.cov_rho_theta, e.rhoTheta(), yaw, t);
    }
    out.location = T_to_from * stairs.location;
    const Eigen::Vector3d heading_dir(std::cos(stairs.heading_rad), std::sin(stairs.heading_rad),
                                      0.0);
    const Eigen::Vector3d h = R * heading_dir;
    out.heading_rad = std::atan2(h.y(), h.x());
    return out;
}

}  // namespace stairmap
