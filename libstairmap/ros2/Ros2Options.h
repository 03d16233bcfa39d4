#pragma once
// Options of stairmap's ROS 2 endpoints, with their defaults (the CLI fills them).

#include <Eigen/Geometry>
#include <cstddef>
#include <string>

#include "pipeline/MapperParams.h"
#include "ros2/PointCloudDecoder.h"
#include "ros2/PoseBuffer.h"

namespace stairmap::ros2 {

/// Ros2Source: clouds and odometry in, robot-frame scans out.
struct Ros2SourceOptions {
    std::string points_topic = "/points";  ///< sensor_msgs/PointCloud2, in the sensor frame
    std::string odom_topic = "/odom";      ///< nav_msgs/Odometry: child_frame_id (robot) in frame_id (world)
    /// T_robot_sensor: where the clouds' frame is on the robot (no TF: from [sensor] pose_*).
    Eigen::Isometry3d T_robot_sensor = Eigen::Isometry3d::Identity();
    bool static_robot = false;    ///< ignore odometry; every scan at the identity pose
    double pose_wait_s = 1.0;     ///< [s] wall time a cloud waits for odometry at or after its stamp
    std::size_t max_waiting_clouds = 50;  ///< [-] clouds waiting for odometry; beyond, the oldest goes
    PoseBufferParams poses;       ///< interpolation limits
    CloudDecodeLimits limits;     ///< refused cloud sizes
    std::string sensor_label = "ros2";  ///< Scan::sensor_label of the scans made
};

/// Ros2LandmarkPublisher: the landmark map out.
struct Ros2PublisherOptions {
    std::string frame_id = "map";      ///< header.frame_id of everything published (the world frame)
    std::string robot_name;            ///< non-empty: topics go under /<robot_name>/...
    std::string markers_topic = "/stairmap/markers";        ///< visualization_msgs/MarkerArray
    std::string staircases_topic = "/stairmap/staircases";  ///< stairmap_msgs/StaircaseArray
};

/// Ros2ScanPublisher (`stairmap play --ros2`): scans out as clouds and odometry.
struct Ros2PlayOptions {
    std::string points_topic = "/points";
    std::string odom_topic = "/odom";
    std::string cloud_frame_id = "lidar";     ///< header.frame_id of the clouds (the sensor frame)
    std::string odom_frame_id = "odom";       ///< Odometry header.frame_id (the world frame)
    std::string base_frame_id = "base_link";  ///< Odometry child_frame_id (the robot frame)
};

/// T_robot_sensor from [sensor] pose_x_m .. pose_roll_deg (yaw-pitch-roll about z, y', x'').
Eigen::Isometry3d sensorPoseOnRobot(const pipeline::SensorParams& sensor);

}  // namespace stairmap::ros2
