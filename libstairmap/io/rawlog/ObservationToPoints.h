#pragma once
// THE one place where MRPT 3D observations become stairmap points in the ROBOT frame.
//
// Frame math is done here, never by MRPT's insertObservation (MRPT 2.5.8 ignores the robot pose
// for CObservationPointCloud in CSimplePointsMap, and skips sensorPose for the points in COctoMap).
// Supported:
//   - CObservationPointCloud:  points are in the sensor frame; we apply sensorPose (T_robot_sensor).
//   - CObservationVelodyneScan: raw packets decoded by our own VelodyneDecoder (all returns),
//                               then sensorPose applied.
//   - CObservation3DRangeScan: MRPT unprojectInto() with takeIntoAccountSensorPoseOnRobot=true.
// A Velodyne scan of another model (not VLP-16 / HDL-32E) is not convertible, with the reason.
// Everything else (CObservationRotatingScan: MRPT 2.5 stores no ring elevations; 2D range scans:
// no use for stair detection; GPS, IMU, poses, ...) is "not convertible", with its class name.
// Non-finite points are dropped and counted.

#include <mrpt/obs/CObservation.h>

#include <cstddef>
#include <string>

#include "core/PointCloud.h"

namespace stairmap::io {

/// Options of the conversion ([sensor] section of the config).
struct ObservationConversionParams {
    float velodyne_min_range_m = 1.0f;    ///< [m] Velodyne returns closer than this are dropped
    float velodyne_max_range_m = 130.0f;  ///< [m] Velodyne returns farther than this are dropped
};

/// Result of converting one observation.
struct ObservationPoints {
    bool convertible = false;          ///< false: the type cannot be turned into 3D points
    std::string type_name;             ///< MRPT class name as registered, e.g. "mrpt::obs::CObservationPointCloud"
    std::string reason;                ///< why not convertible (empty when convertible)
    PointCloud points_robot;           ///< [m] robot frame (x forward, y left, z up)
    std::size_t dropped_non_finite = 0;  ///< points dropped for NaN/Inf coordinates
};

/// Converts one observation to points in the robot frame (sensor extrinsics applied, robot pose not).
/// Never throws for an unsupported type (convertible=false); may throw std::runtime_error if the
/// observation's own data are inconsistent (e.g. externally stored cloud that cannot be loaded).
/// Cost: linear in the number of points / packets.
ObservationPoints observationToRobotPoints(const mrpt::obs::CObservation& obs,
                                           const ObservationConversionParams& params = {});

/// True for the types observationToRobotPoints() can convert (cheap type check, no conversion).
bool isConvertible3DObservation(const mrpt::obs::CObservation& obs);

}  // namespace stairmap::io
