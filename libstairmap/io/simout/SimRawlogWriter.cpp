#include "io/simout/SimRawlogWriter.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <stdexcept>

#include "io/rawlog/PoseConversion.h"

namespace stairmap::io {

namespace {
/// Rounds to a multiple of `quantum`. The float then has its low mantissa bits zero, which lets
/// gzip shrink the rawlog by about a third (2^-9 m) or more (2^-8 m: another ~15 %).
float quantize(float v, float quantum) { return std::round(v / quantum) * quantum; }
}  // namespace

struct SimRawlogWriter::Impl {
    mrpt::io::CFileGZOutputStream file;
};

SimRawlogWriter::SimRawlogWriter(const std::string& path, int gzip_level, double quantum_m)
    : impl_(std::make_unique<Impl>()), path_(path), quantum_m_(static_cast<float>(quantum_m)) {
    if (gzip_level < 1 || gzip_level > 9)
        throw std::invalid_argument(path + ": gzip level must be 1..9");
    if (!(quantum_m > 0 && quantum_m <= 0.05))
        throw std::invalid_argument(path + ": coordinate quantum must be in (0, 0.05] m");
    if (!impl_->file.open(path, gzip_level)) throw std::runtime_error(path + ": cannot open for writing");
}

SimRawlogWriter::~SimRawlogWriter() {
    try {
        close();
    } catch (...) {  // destructors must not throw; close() explicitly to see errors
    }
}

void SimRawlogWriter::close() {
    if (impl_ && impl_->file.is_open()) impl_->file.close();
}

void SimRawlogWriter::writeScan(double stamp_s, const Eigen::Isometry3d& T_world_robot,
                                const Eigen::Matrix<double, 6, 6>& covariance_xyzypr,
                                const Eigen::Isometry3d& T_robot_sensor,
                                const PointCloud& points_sensor, const std::string& sensor_label) {
    if (!impl_->file.is_open()) throw std::runtime_error(path_ + ": writer already closed");
    const auto stamp = mrpt::Clock::fromDouble(stamp_s);
    auto archive = mrpt::serialization::archiveFrom(impl_->file);

    mrpt::obs::CObservationRobotPose pose_obs;
    pose_obs.sensorLabel = "robot_pose";
    pose_obs.timestamp = stamp;
    pose_obs.pose.mean = toCPose3D(T_world_robot);
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c) pose_obs.pose.cov(r, c) = covariance_xyzypr(r, c);
    archive << pose_obs;

    auto map = mrpt::maps::CSimplePointsMap::Create();
    map->reserve(points_sensor.size());
    for (const auto& p : points_sensor) {
        map->insertPointFast(quantize(p.x(), quantum_m_), quantize(p.y(), quantum_m_),
                             quantize(p.z(), quantum_m_));
    }
    mrpt::obs::CObservationPointCloud cloud_obs;
    cloud_obs.sensorLabel = sensor_label;
    cloud_obs.timestamp = stamp;
    cloud_obs.sensorPose = toCPose3D(T_robot_sensor);
    cloud_obs.pointcloud = map;
    archive << cloud_obs;
    ++scans_;
}

}  // namespace stairmap::io
