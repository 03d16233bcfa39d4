#pragma once
// `stairmap live --sensor F.ini`: MRPT sensor drivers as a live, lossy scan source.
// Every sensor section of the INI (rawlog-grabber's format, see DriverIni.h) gets its driver and a
// thread running the driver loop. Each 3D observation becomes a robot-frame Scan through
// io/rawlog's observationToRobotPoints (stairmap's own Velodyne decoder, all returns; not MRPT's
// generatePointCloud, which decodes half of each block in 2.5.8), exactly as `stairmap map` does;
// other observations (the Velodyne's GPS packets, ...) are counted and ignored.
// Robot poses: a growing TUM file (re-read as it grows; a scan whose pose is not known yet waits
// up to pose_wait_s, then is counted as without pose) or a static robot (identity).
//
// Timestamps: MRPT's CVelodyneScanner stamps a rotation with the computer clock until its GPS
// position packets give satellite time, then with satellite time (in the bundled capture the
// first rotation is stamped 2026, the rest 2016), so by default a scan is stamped with the
// computer clock when it arrives (Stamps::Arrival): monotonic, and the clock a pose estimator on
// the same computer writes. Stamps::Sensor keeps the driver's stamps (for a pose file in the
// sensor's time, e.g. made offline from the same capture).

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>

#include "io/rawlog/ObservationToPoints.h"
#include "live/LiveSource.h"
#include "pipeline/MapperParams.h"
#include "sensors/PoseWait.h"

namespace stairmap::sensors {

struct SensorSourceOptions {
    std::string poses_path;     ///< growing TUM file of robot poses (empty: static_robot)
    bool static_robot = false;  ///< identity pose for every scan (a sensor standing still)
    enum class Stamps { Arrival, Sensor };
    Stamps stamps = Stamps::Arrival;  ///< see the file comment
    PoseWaitParams pose_wait;         ///< how long and how many scans wait for their pose
    /// Sensor pose on the robot from stairmap's config ([sensor] pose_*). When set, it replaces
    /// the pose in every observation; a driver section that sets pose_x .. pose_roll as well is
    /// an error (two poses for one sensor). Unset: the driver's pose_* keys (default identity).
    std::optional<Eigen::Isometry3d> T_robot_sensor;
    io::ObservationConversionParams conversion;  ///< Velodyne range limits (as `map`)
    /// Only 3D observations with this label ([sensor] label_filter); MRPT's Velodyne driver labels
    /// its scans "<sensorLabel>_SCAN", so either form matches. Empty: all.
    std::string sensor_label;
    double poll_period_s = 0.02;  ///< [s] how often waiting scans and the pose file are looked at
    double keep_poses_s = 30.0;   ///< [s] poses older than this before the newest delivered scan are forgotten
};

/// T_robot_sensor from [sensor] pose_x_m .. pose_roll_deg (MRPT's yaw-pitch-roll order);
/// std::nullopt when all six are zero (nothing configured).
std::optional<Eigen::Isometry3d> sensorPoseOnRobot(const pipeline::SensorParams& sensor);

/// Opens the INI and initialises every driver (pcap opened and checked, UDP sockets bound) before
/// returning, so bad input fails here, before any output is touched. Throws std::runtime_error
/// naming the INI file and section (unknown driver class, bad key, unreadable or empty pcap), or
/// the pose file; std::invalid_argument if neither poses_path nor static_robot is given.
std::unique_ptr<live::LiveSource> makeSensorSource(const std::string& ini_path,
                                                   const SensorSourceOptions& options);

}  // namespace stairmap::sensors
