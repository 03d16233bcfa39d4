// The simulator's rawlog read back by MRPT: same order, labels, stamps, poses and points.

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>

#include "io/simout/SimRawlogWriter.h"

namespace stairmap::io {
namespace {

Eigen::Isometry3d pose(double x, double y, double z, double yaw, double pitch = 0.0) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY())).toRotationMatrix();
    T.translation() << x, y, z;
    return T;
}

std::string tempPath(const std::string& name) {
    const auto dir = std::filesystem::path(STAIRMAP_TEST_TMP) / "sim_rawlog";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

TEST(SimRawlogWriter, MrptReadsBackPosesThenCloudsWithTheSameStamps) {
    const std::string path = tempPath("three_scans.rawlog");
    const Eigen::Isometry3d T_robot_sensor = pose(0.1, 0.0, 0.4, 0.0, 0.2);
    std::vector<Eigen::Isometry3d> poses = {pose(0, 0, 0.35, 0), pose(1.5, -0.5, 0.4, 0.3),
                                            pose(2.0, 3.0, 3.35, -2.0)};
    std::vector<PointCloud> clouds(3);
    for (int k = 0; k < 3; ++k) {
        for (int i = 0; i < 50 + k; ++i) clouds[k].emplace_back(0.1f * i, -0.05f * i + k, 0.3f);
    }
    Eigen::Matrix<double, 6, 6> cov = Eigen::Matrix<double, 6, 6>::Identity() * 0.01;
    {
        SimRawlogWriter writer(path, 3);
        for (int k = 0; k < 3; ++k) writer.writeScan(100.0 + k, poses[k], cov, T_robot_sensor, clouds[k]);
        EXPECT_EQ(writer.scansWritten(), 3u);
    }
    mrpt::io::CFileGZInputStream file(path);
    auto archive = mrpt::serialization::archiveFrom(file);
    mrpt::obs::CActionCollection::Ptr action;
    mrpt::obs::CSensoryFrame::Ptr frame;
    mrpt::obs::CObservation::Ptr obs;
    std::size_t entry = 0;
    std::vector<mrpt::obs::CObservation::Ptr> read;
    while (mrpt::obs::CRawlog::getActionObservationPairOrObservation(archive, action, frame, obs, entry)) {
        ASSERT_TRUE(obs) << "expected observations-only format";
        read.push_back(obs);
    }
    ASSERT_EQ(read.size(), 6u);
    for (int k = 0; k < 3; ++k) {
        auto pose_obs = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(read[2 * k]);
        auto cloud_obs = std::dynamic_pointer_cast<mrpt::obs::CObservationPointCloud>(read[2 * k + 1]);
        ASSERT_TRUE(pose_obs && cloud_obs) << "scan " << k;
        EXPECT_EQ(pose_obs->sensorLabel, "robot_pose");
        EXPECT_EQ(cloud_obs->sensorLabel, "lidar");
        EXPECT_EQ(pose_obs->timestamp, cloud_obs->timestamp);
        EXPECT_NEAR(mrpt::Clock::toDouble(pose_obs->timestamp), 100.0 + k, 1e-5);
        const auto m = pose_obs->pose.mean.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>();
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(m(r, c), poses[k].matrix()(r, c), 1e-9);
        EXPECT_NEAR(pose_obs->pose.cov(0, 0), 0.01, 1e-12);
        const auto s = cloud_obs->sensorPose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>();
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(s(r, c), T_robot_sensor.matrix()(r, c), 1e-9);
        ASSERT_TRUE(cloud_obs->pointcloud);
        ASSERT_EQ(cloud_obs->pointcloud->size(), clouds[k].size());
        for (std::size_t i = 0; i < clouds[k].size(); ++i) {
            float x, y, z;
            cloud_obs->pointcloud->getPoint(i, x, y, z);
            // Coordinates are quantised to 2^-9 m.
            EXPECT_NEAR(x, clouds[k][i].x(), 1.0 / 1024 + 1e-6);
            EXPECT_NEAR(y, clouds[k][i].y(), 1.0 / 1024 + 1e-6);
            EXPECT_NEAR(z, clouds[k][i].z(), 1.0 / 1024 + 1e-6);
        }
    }
}

TEST(SimRawlogWriter, UnwritablePathThrowsNamingIt) {
    try {
        SimRawlogWriter writer("/nonexistent_dir_stairmap/x.rawlog");
        FAIL() << "expected an exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent_dir_stairmap/x.rawlog"), std::string::npos);
    }
}

}  // namespace
}  // namespace stairmap::io
