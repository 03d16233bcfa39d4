#pragma once
// Single accumulated clouds in the robot frame (a robot that paused and gathered a few scans),
// with the ground truth expressed in the same frame, for `stairmap detect` and `stairmap eval`.

#include <Eigen/Geometry>
#include <random>

#include "core/GroundTruth.h"
#include "core/PointCloud.h"
#include "sim/Scene.h"
#include "sim/SensorModel.h"

namespace stairmap::sim {

struct CloudSampleParams {
    int scans_per_cloud = 3;         ///< scans accumulated into one cloud
    double jitter_xy_m = 0.01;       ///< [m] std of the per-scan position wobble (true, known)
    double jitter_yaw_deg = 0.3;     ///< [deg] std of the per-scan heading wobble
    double jitter_tilt_deg = 0.0;    ///< [deg] std of per-scan body pitch/roll (a legged robot's
                                     ///< sway spreads the rings over the treads)
    double floor_tolerance_m = 0.05; ///< [m] observer floor vs stair bottom/top to set seen_as
    /// [m] round every coordinate to a multiple of this (0: keep float32 as is). Quantised values
    /// have zero low mantissa bits, which lets a gzipped cloud file shrink to about a third; keep it
    /// well below the range noise (2^-8 m = 3.9 mm adds 1.1 mm rms to 1 cm noise).
    double quantum_m = 0.0;
    /// Sort the points by (x, y, z) so equal quantised x values sit together and gzip finds them
    /// (the detector does not depend on the point order; a scan-ordered cloud compresses ~15 % worse).
    bool sort_points = false;
};

/// Throws std::invalid_argument naming the field if a parameter is out of range.
void validate(const CloudSampleParams& params);

/// Points [m] in the robot frame at T_world_robot; each scan comes from a slightly wobbled pose and
/// a random azimuth start, and is mapped back with its true pose (no registration error). The
/// result is quantised / sorted as `params` ask.
PointCloud simulateRobotCloud(const Scene& scene, const Eigen::Isometry3d& T_world_robot,
                              const Eigen::Isometry3d& T_robot_sensor, const SensorParams& sensor,
                              const CloudSampleParams& params, std::mt19937& rng);

/// Rounds coordinates to multiples of quantum_m (if > 0) and sorts by (x, y, z) (if sort).
void quantizeAndSort(PointCloud& cloud, double quantum_m, bool sort);

/// The scene's truth in the robot frame; sets observer_floor_z and each staircase's seen_as
/// (ascending if the robot stands on its bottom floor, descending if on its top floor).
SceneTruth truthInRobotFrame(const SceneTruth& world_truth, const Eigen::Isometry3d& T_world_robot,
                             double floor_z_world, double floor_tolerance_m = 0.05);

}  // namespace stairmap::sim
