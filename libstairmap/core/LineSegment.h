#pragma once
// A horizontal line segment found in one z row of the cylindrical array (paper Sec. III-B):
// XY end points, height, Hessian line parameters and their covariance from the weighted fit.

#include <Eigen/Core>
#include <cmath>

namespace stairmap {

struct LineSegment {
    Eigen::Vector2d start = Eigen::Vector2d::Zero();  ///< [m] XY end point (first in azimuth order)
    Eigen::Vector2d end = Eigen::Vector2d::Zero();    ///< [m] XY end point (last)
    double z = 0.0;                                   ///< [m] mean height of the supporting points
    double rho = 0.0;                                 ///< [m] Hessian distance, >= 0
    double theta = 0.0;                               ///< [rad] Hessian normal angle
    Eigen::Matrix2d cov = Eigen::Matrix2d::Identity();  ///< covariance of (rho, theta)
    int num_points = 0;

    double length() const { return (end - start).norm(); }
    Eigen::Vector2d centre() const { return 0.5 * (start + end); }
    /// Unit direction along the line (perpendicular to the normal).
    Eigen::Vector2d direction() const { return {-std::sin(theta), std::cos(theta)}; }
    /// Unit XY normal pointing away from `p` (from p's side of the line towards the line; a point
    /// on the line gets either): up a flight, from a lower edge to this one.
    Eigen::Vector2d normalAwayFrom(const Eigen::Vector2d& p) const {
        const Eigen::Vector2d d = direction();
        const Eigen::Vector2d n(d.y(), -d.x());
        return n.dot(centre() - p) < 0 ? Eigen::Vector2d(-n) : n;
    }
    /// Signed XY distance of a point to the infinite line.
    double distanceTo(const Eigen::Vector2d& p) const {
        return p.x() * std::cos(theta) + p.y() * std::sin(theta) - rho;
    }
};

}  // namespace stairmap
