#pragma once
// Writes the simulator's MRPT rawlog (observations-only format, gzip-compressed): per scan a
// CObservationRobotPose (label "robot_pose": the pose handed to the mapper, with covariance) FIRST,
// then a CObservationPointCloud (points in the SENSOR frame, sensorPose = T_robot_sensor) with the
// same timestamp. Coordinates are quantised (default 2^-9 m, ~2 mm) so gzip can shrink the file.

#include <Eigen/Geometry>
#include <memory>
#include <string>

#include "core/PointCloud.h"

namespace stairmap::io {

class SimRawlogWriter {
public:
    /// Default coordinate quantum [m]: 2^-9 (~2 mm, below a VLP-16's range resolution).
    static constexpr double kDefaultQuantumM = 1.0 / 512.0;

    /// Opens `path` for writing (gzip level 1..9). Sensor-frame coordinates are rounded to
    /// multiples of quantum_m (0 < quantum_m <= 0.05) [m]. Throws std::invalid_argument for a bad
    /// level or quantum, std::runtime_error naming the path if it cannot be opened.
    explicit SimRawlogWriter(const std::string& path, int gzip_level = 6,
                             double quantum_m = kDefaultQuantumM);
    ~SimRawlogWriter();
    SimRawlogWriter(const SimRawlogWriter&) = delete;
    SimRawlogWriter& operator=(const SimRawlogWriter&) = delete;

    /// Appends one scan. covariance_xyzypr: 6x6 in MRPT CPose3D order (x, y, z, yaw, pitch, roll).
    void writeScan(double stamp_s, const Eigen::Isometry3d& T_world_robot,
                   const Eigen::Matrix<double, 6, 6>& covariance_xyzypr,
                   const Eigen::Isometry3d& T_robot_sensor, const PointCloud& points_sensor,
                   const std::string& sensor_label = "lidar");

    /// Flushes and closes; called by the destructor too.
    void close();

    std::size_t scansWritten() const { return scans_; }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::string path_;
    float quantum_m_;
    std::size_t scans_ = 0;
};

}  // namespace stairmap::io
