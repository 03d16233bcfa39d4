#pragma once
// The detector's output model (paper Sec. III-C/D): a staircase is an ordered list of step edges
// plus the geometry estimated from them.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace stairmap {

/// One step edge, a horizontal segment. Convention (shared with the simulator's ground truth): every
/// edge is a NOSING, where a tread (or a floor/landing) meets the top of the riser below it, at the
/// tread's height. Edges made by the detector run from `start` (left) to `end` (right) when facing
/// along the staircase heading.
struct StairEdge {
    Eigen::Vector3d start = Eigen::Vector3d::Zero();  ///< [m] one end of the edge
    Eigen::Vector3d end = Eigen::Vector3d::Zero();    ///< [m] the other end
    /// Covariance of the supporting infinite line in Hessian normal form (rho [m], theta [rad]),
    /// rho = x cos(theta) + y sin(theta), expressed in the frame the edge is given in.
    Eigen::Matrix2d cov_rho_theta = Eigen::Matrix2d::Identity() * 1e-4;
    int num_points = 0;  ///< points that supported the weighted line fit

    /// Orientation alpha of the edge in the XY plane [rad], folded into (-pi/2, pi/2].
    double orientationRad() const;
    Eigen::Vector3d centre() const { return 0.5 * (start + end); }
    double length() const { return (end - start).norm(); }
    /// Hessian normal form (rho [m], theta [rad]) of the supporting XY line: the normal
    /// (cos theta, sin theta) points from the frame origin to the line, so rho >= 0.
    /// This is the parametrisation cov_rho_theta refers to.
    Eigen::Vector2d rhoTheta() const;
};

enum class StairDirection { Ascending, Descending };

/// What ends the treads on one side of a flight (core/StepExtent.h): a wall (points rising above
/// the tread just beyond its end), an open edge that was seen (floor or a drop visible beyond the
/// end), or unseen (the view does not cover beyond the end, so the width may be short there).
enum class StairSide { Unseen, Wall, Open };

/// A detected staircase. `steps` are ordered from the floor the observer stands on outward
/// (ascending: bottom to top; descending: top to bottom).
struct Staircase {
    StairDirection direction = StairDirection::Ascending;
    std::vector<StairEdge> steps;
    double step_height = 0.0;        ///< [m] mean rise
    double step_depth = 0.0;         ///< [m] mean run
    double step_width = 0.0;         ///< [m] mean edge length
    double slope_rad = 0.0;          ///< atan(step_height / step_depth)
    Eigen::Vector3d location = Eigen::Vector3d::Zero();  ///< [m] centre of steps.front()
    /// Direction of travel along the flight [rad], counter-clockwise from +x: up the stairs for an
    /// ascending staircase, down them for a descending one.
    double heading_rad = 0.0;
    /// Sides, looking along heading_rad (left = the edges' `start` side). A width is complete
    /// when both sides are bounded (Wall or Open).
    StairSide left_side = StairSide::Unseen;
    StairSide right_side = StairSide::Unseen;
};

/// "wall", "open", "unseen" (JSON values).
const char* stairSideName(StairSide side);
/// Inverse of stairSideName; false (and `side` unchanged) for another string.
bool stairSideFromName(const std::string& name, StairSide& side);

}  // namespace stairmap
