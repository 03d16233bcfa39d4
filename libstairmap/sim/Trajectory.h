#pragma once
// Robot trajectories for the simulator: a scripted path through waypoints at a given speed and
// scan rate, and odometry/SLAM drift applied to the poses handed to the mapper.

#include <Eigen/Geometry>
#include <random>
#include <vector>

namespace stairmap::sim {

struct TrajectoryParams {
    /// Ground contact points (x, y, floor z) [m]. The robot frame origin is base_height_m above
    /// them; on stairs give the floor heights at the foot and head of the flight and the path
    /// interpolates linearly between them (a legged robot's body follows the slope).
    std::vector<Eigen::Vector3d> waypoints;
    double speed_mps = 0.8;            ///< [m/s] along the path (3D length)
    double yaw_rate_dps = 60.0;        ///< [deg/s] turn in place at waypoints
    double scan_rate_hz = 2.0;         ///< [Hz] scans per second
    double start_time_s = 1.7e9;       ///< [s] stamp of the first scan (UNIX time)
    double base_height_m = 0.35;       ///< [m] robot frame origin above the floor
};

/// Drift on the poses handed to the mapper: each step's motion is perturbed by zero-mean Gaussian
/// noise whose standard deviation grows with the distance travelled in that step.
struct DriftParams {
    double xy_std_per_m = 0.0;        ///< [m/m] translation noise per metre travelled
    double z_std_per_m = 0.0;         ///< [m/m] height noise per metre travelled
    double yaw_std_deg_per_m = 0.0;   ///< [deg/m] heading noise per metre travelled
    unsigned seed = 1;
};

/// Body sway of a walking legged robot: each scan's true pose gets a random pitch and roll about
/// the robot origin (the scan rings then fall at other heights on the treads, as on a real robot).
/// The reported poses carry the same tilt: an IMU measures roll and pitch well; drift is in x, y,
/// z and yaw only.
struct SwayParams {
    double tilt_std_deg = 0.0;  ///< [deg] std of pitch and of roll per scan (0: no sway)
    unsigned seed = 1;
};

/// One scan time with the true pose and the pose reported to the mapper.
struct TrajectorySample {
    double stamp_s = 0.0;
    Eigen::Isometry3d T_world_robot_true = Eigen::Isometry3d::Identity();
    Eigen::Isometry3d T_world_robot_reported = Eigen::Isometry3d::Identity();
    /// Covariance of the reported pose, MRPT CPose3D order (x, y, z, yaw, pitch, roll) [m^2, rad^2].
    Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Identity() * 1e-6;
};

/// Throws std::invalid_argument naming the field if a parameter is out of range.
void validate(const TrajectoryParams& params);

/// Samples the path at scan_rate_hz; reported poses equal the true ones (no drift yet).
/// The robot turns in place to face each segment, then drives it at speed_mps.
std::vector<TrajectorySample> sampleTrajectory(const TrajectoryParams& params);

/// Tilts the true poses by the sway and sets the reported poses to them (call before applyDrift).
/// No random draws when tilt_std_deg is 0 (the samples are left as they are).
void applySway(std::vector<TrajectorySample>& samples, const SwayParams& sway);

/// Replaces the reported poses with drifting ones (the true poses are untouched).
void applyDrift(std::vector<TrajectorySample>& samples, const DriftParams& drift);

/// Robot pose at a ground point with heading yaw [rad]: origin base_height above the floor.
Eigen::Isometry3d robotPoseAt(const Eigen::Vector3d& ground, double yaw_rad, double base_height);

}  // namespace stairmap::sim
