#pragma once
// Helpers for io tests: build small rawlogs in memory and write them in either format.

#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement3D.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

namespace stairmap::test {

/// A fresh scratch folder per test: STAIRMAP_TEST_TMP/<suite>_<test>.
inline std::string scratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    for (char& c : name) {
        if (c == '/') c = '_';
    }
    const std::filesystem::path dir = std::filesystem::path(STAIRMAP_TEST_TMP) / "io" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

inline mrpt::Clock::time_point stamp(double t_s) { return mrpt::Clock::fromDouble(t_s); }

inline mrpt::obs::CObservationPointCloud::Ptr makeCloudObs(
    double t_s, const mrpt::poses::CPose3D& T_robot_sensor,
    const std::vector<Eigen::Vector3f>& points_sensor, const std::string& label = "lidar") {
    auto obs = mrpt::obs::CObservationPointCloud::Create();
    auto map = mrpt::maps::CSimplePointsMap::Create();
    for (const auto& p : points_sensor) map->insertPointFast(p.x(), p.y(), p.z());
    obs->pointcloud = map;
    obs->sensorPose = T_robot_sensor;
    obs->sensorLabel = label;
    obs->timestamp = stamp(t_s);
    return obs;
}

inline mrpt::obs::CObservationRobotPose::Ptr makePoseObs(double t_s,
                                                        const mrpt::poses::CPose3D& T_world_robot) {
    auto obs = mrpt::obs::CObservationRobotPose::Create();
    obs->pose.mean = T_world_robot;
    obs->sensorLabel = "robot_pose";
    obs->timestamp = stamp(t_s);
    return obs;
}

inline mrpt::obs::CActionCollection makeMove3D(const mrpt::poses::CPose3D& increment) {
    mrpt::obs::CActionRobotMovement3D move;
    move.poseChange.mean = increment;
    mrpt::obs::CActionCollection acts;
    acts.insert(move);
    return acts;
}

/// Writes serializable objects in order to a plain or gz file.
class RawlogWriter {
public:
    RawlogWriter(const std::string& path, bool gz) {
        if (gz) {
            gz_.open(path, 1);
            ar_ = mrpt::serialization::archiveUniquePtrFrom(gz_);
        } else {
            plain_.open(path);
            ar_ = mrpt::serialization::archiveUniquePtrFrom(plain_);
        }
    }
    template <typename T>
    RawlogWriter& operator<<(const T& object) {
        *ar_ << object;
        return *this;
    }

private:
    mrpt::io::CFileGZOutputStream gz_;
    mrpt::io::CFileOutputStream plain_;
    mrpt::serialization::CArchive::UniquePtr ar_;
};

}  // namespace stairmap::test
