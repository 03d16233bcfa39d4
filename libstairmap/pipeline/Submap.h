#pragma once
// The detector's local cloud: recent scans (world frame) cut around the robot and expressed in the
// gravity-aligned robot frame ("grav"): origin at the robot, x along the robot's heading projected
// on the horizontal plane (yaw only: roll and pitch removed), z up. The floor the robot stands on
// is then at z = -robot_height.

#include <Eigen/Geometry>
#include <cstddef>
#include <deque>

#include "core/PointCloud.h"
#include "pipeline/MapperParams.h"

namespace stairmap::pipeline {

/// Yaw of the robot: the heading of its x axis projected on the world xy plane [rad].
double robotYaw(const Eigen::Isometry3d& T_world_robot);

/// T_world_grav: translation of the robot, rotation about world z by the robot's yaw.
Eigen::Isometry3d gravityAlignedFrame(const Eigen::Isometry3d& T_world_robot);

/// A rolling window of recent scans in the world frame: at most `max_scans`, none older than
/// `max_age_s` relative to the newest. Memory: bounded by max_scans x points per scan.
class ScanWindow {
public:
    ScanWindow(int max_scans, double max_age_s);

    void push(double stamp_s, PointCloud points_world);
    std::size_t numScans() const { return scans_.size(); }
    std::size_t numPoints() const;

    /// Points within `radius_m` (horizontal distance) of T_world_grav's origin, expressed in the
    /// grav frame, voxel-downsampled to `leaf_m` (<= 0: no downsampling). Cost: O(window points).
    PointCloud extractSubmap(const Eigen::Isometry3d& T_world_grav, double radius_m,
                             double leaf_m) const;

private:
    struct Entry {
        double stamp_s;
        PointCloud points_world;
    };
    std::deque<Entry> scans_;
    int max_scans_;
    double max_age_s_;
};

/// Keeps one point (the first) per cubic voxel of edge leaf_m. Cost: O(n) expected.
PointCloud voxelDownsample(const PointCloud& cloud, double leaf_m);

}  // namespace stairmap::pipeline
