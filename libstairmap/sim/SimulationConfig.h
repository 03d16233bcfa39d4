#pragma once
// Everything `stairmap sim` needs to run one scene: the world, the sensor and its mounting, the
// robots' trajectories (for rawlogs) and the sample poses (for single clouds).

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "sim/CloudSampler.h"
#include "sim/Scene.h"
#include "sim/SensorModel.h"
#include "sim/Trajectory.h"

namespace stairmap::sim {

/// A LiDAR/depth camera and where it sits on the robot.
struct MountedSensor {
    SensorParams sensor;
    std::string label = "lidar";  ///< label of the point-cloud observations
    Eigen::Isometry3d T_robot_sensor = Eigen::Isometry3d::Identity();
};

/// One robot driving a scripted path; its rawlog gets `name` in the file names.
struct RobotRun {
    std::string name = "robot";
    TrajectoryParams trajectory;
    DriftParams drift;
    SwayParams sway;
    /// The robot's own sensor (robots of one scene may differ, e.g. a level LiDAR on a wheeled
    /// robot and a pitched one on a legged robot); the loader fills it from [sensor] by default.
    MountedSensor mounted;
    /// The robot's own (odometry) frame in the world: its reported poses (rawlog robot_pose,
    /// poses.tum) are T_odom_robot = T_world_odom^-1 * T_world_robot; the truth stays in the world
    /// frame. Identity: the robot reports world poses.
    Eigen::Isometry3d T_world_odom = Eigen::Isometry3d::Identity();
};

/// A place where a single accumulated cloud is taken: the robot stands on (x, y, floor_z) facing yaw.
struct CloudPose {
    Eigen::Vector3d ground = Eigen::Vector3d::Zero();  ///< [m] (x, y, floor z)
    double yaw_deg = 0.0;                              ///< [deg]
};

struct SimulationConfig {
    std::string name = "scene";            ///< output prefix (clouds: <name>_<i>.pcd)
    std::string kind = "ascending";        ///< stair kind label of the scene's clouds
    unsigned seed = 1;                     ///< seeds sensor noise (the CLI can override it)
    Scene scene;
    SensorParams sensor;
    std::string sensor_label = "lidar";    ///< label of the point-cloud observations
    Eigen::Isometry3d T_robot_sensor = Eigen::Isometry3d::Identity();
    double base_height_m = 0.35;           ///< [m] robot frame origin above the floor
    std::vector<RobotRun> robots;          ///< empty: the scene makes clouds only
    double rawlog_quantum_m = 1.0 / 512.0; ///< [m] rawlog coordinates are multiples of this
    bool rawlog_sort_points = false;       ///< sort each scan's points by (x, y, z) (gzip: smaller)
    std::vector<CloudPose> cloud_poses;    ///< empty: the scene makes rawlogs only
    CloudSampleParams cloud_params;
    std::string cloud_extension = "pcd";   ///< pcd | ply | xyz, each optionally + ".gz"
    int cloud_first_index = 0;             ///< number of the first cloud file
};

}  // namespace stairmap::sim
