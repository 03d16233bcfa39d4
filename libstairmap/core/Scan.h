#pragma once
// One 3D scan handed down the mapping chain, and the one-method interface every scan source implements.

#include <Eigen/Geometry>
#include <cstddef>
#include <optional>
#include <string>

#include "core/PointCloud.h"

namespace stairmap {

/// A scan already converted to the robot frame (the sensor's extrinsics applied), with the robot pose.
struct Scan {
    std::size_t index = 0;        ///< 0-based index of this scan in its source
    double stamp_s = 0.0;         ///< [s] timestamp (UNIX or log time; only differences matter)
    std::string sensor_label;     ///< e.g. "lidar"
    Eigen::Isometry3d T_world_robot = Eigen::Isometry3d::Identity();
    PointCloud points_robot;      ///< [m] points in the robot frame (x forward, y left, z up)
};

/// A stream of scans (rawlog reader, live follower, simulator). next() returns std::nullopt at the
/// end of the stream; it throws std::runtime_error naming the source and scan index on corrupt data.
class ScanSource {
public:
    virtual ~ScanSource() = default;
    virtual std::optional<Scan> next() = 0;
};

}  // namespace stairmap
