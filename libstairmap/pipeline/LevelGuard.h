#pragma once
// Tells whether the robot is on level ground from the slope of its recent path. The detector
// assumes the robot stands on a floor (paper Sec. III-B: the floor height is the robot's), and
// robot floor samples taken on a flight of stairs would invent floors, so the mapper defers
// detection while the robot climbs or descends.

#include <Eigen/Core>
#include <deque>

namespace stairmap::pipeline {

class LevelGuard {
public:
    /// max_slope_deg: steeper recent paths count as climbing (<= 0 disables the guard).
    /// path_window_m: horizontal path length the slope is measured over [m].
    explicit LevelGuard(double max_slope_deg, double path_window_m = 0.6);

    /// Feed every robot position in order; returns true while the robot is on level ground.
    /// A robot that does not move keeps its last state (initially level).
    bool update(const Eigen::Vector3d& position);

private:
    double max_slope_tan_;
    double path_window_m_;
    std::deque<Eigen::Vector3d> recent_;
    bool level_ = true;
};

}  // namespace stairmap::pipeline
