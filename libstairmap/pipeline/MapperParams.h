#pragma once
// All parameters of the mapping pipeline, one struct per config section. Header only (io/ loads it).

#include <string>

#include "core/DetectorParams.h"
#include "map/LandmarkParams.h"
#include "map/VoxelMapParams.h"

namespace stairmap::pipeline {

/// [sensor]: which scans to use and where the floor is relative to the robot frame.
struct SensorParams {
    /// [m] height of the robot frame origin above the floor it stands on: the floor under the
    /// robot is at world z = robot z - robot_height_m, and at z = -robot_height_m in the submap.
    double robot_height_m = 0.0;
    /// Use the robot-pose floor (true) or let the detector estimate the floor from the cloud.
    bool floor_from_pose = true;
    std::string label_filter;  ///< only scans with this sensor label are used (empty: all)
    double min_range_m = 0.3;  ///< [m] points closer to the robot origin are dropped (self hits)
    double max_range_m = 30.0; ///< [m] points farther from the robot origin are dropped
    /// Pose of the sensor on the robot, for live sources whose messages carry none (ROS 2
    /// PointCloud2 without TF, MRPT drivers configured elsewhere). Rawlog observations carry their
    /// own sensor pose and ignore these. [m] translation, [deg] yaw-pitch-roll (MRPT's order).
    double pose_x_m = 0.0, pose_y_m = 0.0, pose_z_m = 0.0;
    double pose_yaw_deg = 0.0, pose_pitch_deg = 0.0, pose_roll_deg = 0.0;
};

/// [scheduling]: when the detector runs and on what cloud.
struct SchedulingParams {
    double distance_m = 1.0;   ///< [m] run after travelling this far since the last run (<= 0: off)
    double angle_deg = 30.0;   ///< [deg] ... or turning this much (<= 0: off)
    double period_s = 5.0;     ///< [s] ... or after this much time (<= 0: off)
    int window_scans = 10;     ///< [-] the rolling window keeps at most this many recent scans
    double window_s = 2.0;     ///< [s] ... none older than this (relative to the newest scan)
    double submap_radius_m = 6.0;  ///< [m] horizontal radius of the detector's submap
    double submap_leaf_m = 0.02;   ///< [m] voxel downsampling of the submap (<= 0: off)
    /// [deg] detection and robot floor samples are deferred while the robot's recent path is
    /// steeper than this (climbing stairs or a ramp; <= 0: never deferred)
    double max_level_slope_deg = 10.0;
};

struct MapperParams {
    SensorParams sensor;
    map::VoxelMapParams map;
    SchedulingParams scheduling;
    DetectorParams detector;
    LandmarkParams landmarks;
};

}  // namespace stairmap::pipeline
