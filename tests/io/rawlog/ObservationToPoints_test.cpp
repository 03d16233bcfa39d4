// Frame math of the one observation -> robot-frame points conversion.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <Eigen/Eigenvalues>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationRotatingScan.h>
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "io/rawlog/ObservationToPoints.h"

using namespace stairmap;
using namespace stairmap::io;

namespace {

mrpt::obs::CObservationPointCloud makeCloud(const mrpt::poses::CPose3D& T_robot_sensor,
                                            const std::vector<Eigen::Vector3f>& pts) {
    mrpt::obs::CObservationPointCloud obs;
    auto map = mrpt::maps::CSimplePointsMap::Create();
    for (const auto& p : pts) map->insertPointFast(p.x(), p.y(), p.z());
    obs.pointcloud = map;
    obs.sensorPose = T_robot_sensor;
    obs.sensorLabel = "lidar";
    return obs;
}

}  // namespace

TEST(ObservationToPoints, PointCloudAppliesSensorPose) {
    // Sensor 0.5 m above the robot origin: sensor point (1,0,0) is robot point (1,0,0.5).
    const auto obs = makeCloud(mrpt::poses::CPose3D(0, 0, 0.5, 0, 0, 0), {{1, 0, 0}});
    const ObservationPoints r = observationToRobotPoints(obs);
    ASSERT_TRUE(r.convertible);
    ASSERT_EQ(r.points_robot.size(), 1u);
    EXPECT_NEAR(r.points_robot[0].x(), 1.0f, 1e-6);
    EXPECT_NEAR(r.points_robot[0].y(), 0.0f, 1e-6);
    EXPECT_NEAR(r.points_robot[0].z(), 0.5f, 1e-6);
}

TEST(ObservationToPoints, PointCloudAppliesSensorRotation) {
    // Sensor yawed +90 deg at (0.2, 0, 0).
    const auto obs = makeCloud(mrpt::poses::CPose3D(0.2, 0, 0, M_PI / 2, 0, 0), {{1, 0, 0}, {0, 0, 2}});
    const ObservationPoints r = observationToRobotPoints(obs);
    ASSERT_EQ(r.points_robot.size(), 2u);
    EXPECT_NEAR(r.points_robot[0].x(), 0.2f, 1e-6);  // sensor x -> robot y
    EXPECT_NEAR(r.points_robot[0].y(), 1.0f, 1e-6);
    EXPECT_NEAR(r.points_robot[1].z(), 2.0f, 1e-6);
    // Pitch the sensor down by 90 deg: its x axis points to robot -z.
    const auto pitched = makeCloud(mrpt::poses::CPose3D(0, 0, 1.0, 0, M_PI / 2, 0), {{2, 0, 0}});
    const ObservationPoints rp = observationToRobotPoints(pitched);
    ASSERT_EQ(rp.points_robot.size(), 1u);
    EXPECT_NEAR(rp.points_robot[0].x(), 0.0f, 1e-5);
    EXPECT_NEAR(rp.points_robot[0].z(), -1.0f, 1e-5);
}

TEST(ObservationToPoints, DropsNonFinitePoints) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const auto obs = makeCloud(mrpt::poses::CPose3D(), {{1, 2, 3}, {nan, 0, 0}, {0, inf, 0}, {4, 5, 6}});
    const ObservationPoints r = observationToRobotPoints(obs);
    ASSERT_TRUE(r.convertible);
    EXPECT_EQ(r.points_robot.size(), 2u);
    EXPECT_EQ(r.dropped_non_finite, 2u);
}

TEST(ObservationToPoints, EmptyCloudIsConvertibleAndEmpty) {
    mrpt::obs::CObservationPointCloud obs;  // no pointcloud at all
    const ObservationPoints r = observationToRobotPoints(obs);
    EXPECT_TRUE(r.convertible);
    EXPECT_TRUE(r.points_robot.empty());
    const ObservationPoints r2 = observationToRobotPoints(makeCloud(mrpt::poses::CPose3D(), {}));
    EXPECT_TRUE(r2.convertible);
    EXPECT_TRUE(r2.points_robot.empty());
}

TEST(ObservationToPoints, UnsupportedTypesNamed) {
    mrpt::obs::CObservationRotatingScan rot;
    const ObservationPoints r = observationToRobotPoints(rot);
    EXPECT_FALSE(r.convertible);
    EXPECT_NE(r.type_name.find("CObservationRotatingScan"), std::string::npos) << r.type_name;
    EXPECT_NE(r.reason.find("CObservationRotatingScan"), std::string::npos) << r.reason;
    EXPECT_FALSE(isConvertible3DObservation(rot));
    mrpt::obs::CObservation2DRangeScan scan2d;
    EXPECT_FALSE(observationToRobotPoints(scan2d).convertible);
}

TEST(ObservationToPoints, EmptyVelodyneScanIsEmpty) {
    mrpt::obs::CObservationVelodyneScan velo;
    const ObservationPoints r = observationToRobotPoints(velo);
    EXPECT_TRUE(r.convertible);
    EXPECT_TRUE(r.points_robot.empty());
    EXPECT_TRUE(isConvertible3DObservation(velo));
}

// A real depth camera (320x240) looking at a bare floor, from MRPT's test data: a bare serialized
// CSensoryFrame. The camera sits 1.27 m up, pitched ~73 deg down; in the robot frame the floor
// must come out as a horizontal plane near z = 0, in front of the robot.
namespace {
mrpt::obs::CObservation3DRangeScan::Ptr readGroundRangeScan() {
    mrpt::io::CFileGZInputStream f(std::string(STAIRMAP_SHARED_DIR) + "/data/real/test-3d-obs-ground.rawlog");
    auto ar = mrpt::serialization::archiveFrom(f);
    auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(ar.ReadObject());
    if (!sf) return nullptr;
    return sf->getObservationByClass<mrpt::obs::CObservation3DRangeScan>();
}
}  // namespace

TEST(ObservationToPoints, RangeScanFloorIsLevelInRobotFrame) {
    const auto obs = readGroundRangeScan();
    ASSERT_TRUE(obs);
    const ObservationPoints r = observationToRobotPoints(*obs);
    ASSERT_TRUE(r.convertible);
    ASSERT_GT(r.points_robot.size(), 10000u);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : r.points_robot) mean += p.cast<double>();
    mean /= double(r.points_robot.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& p : r.points_robot) {
        const Eigen::Vector3d d = p.cast<double>() - mean;
        cov += d * d.transpose();
    }
    cov /= double(r.points_robot.size());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    const Eigen::Vector3d normal = eig.eigenvectors().col(0);
    EXPECT_GT(std::abs(normal.z()), 0.99) << normal.transpose();  // level within ~8 deg
    EXPECT_LT(std::sqrt(eig.eigenvalues()(0)), 0.05);              // flat: < 5 cm rms
    EXPECT_NEAR(mean.z(), 0.0, 0.05);                              // floor at the robot's feet
    EXPECT_GT(mean.x(), 0.2);                                      // in front of the robot
    EXPECT_LT(mean.x(), 2.0);
}

TEST(ObservationToPoints, RangeScanEqualsSensorPointsTimesSensorPose) {
    const auto obs = readGroundRangeScan();
    ASSERT_TRUE(obs);
    const ObservationPoints r = observationToRobotPoints(*obs);
    mrpt::maps::CSimplePointsMap sensor_map;
    obs->unprojectInto(sensor_map);  // sensor frame (takeIntoAccountSensorPoseOnRobot = false)
    ASSERT_EQ(sensor_map.size(), r.points_robot.size());
    const auto H = obs->sensorPose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>();
    for (std::size_t i = 0; i < sensor_map.size(); i += 97) {
        float x, y, z;
        sensor_map.getPoint(i, x, y, z);
        Eigen::Vector3d expected;
        for (int row = 0; row < 3; ++row) {
            expected(row) = H(row, 0) * x + H(row, 1) * y + H(row, 2) * z + H(row, 3);
        }
        EXPECT_LT((r.points_robot[i].cast<double>() - expected).norm(), 1e-4) << i;
    }
}

namespace {
// One synthetic packet: laser channel 0 at 10 m (HDL-32E: -30.67 deg; VLP-16: -15 deg), azimuth 0.
mrpt::obs::CObservationVelodyneScan velodyneWithOneReturn(std::uint8_t product_id,
                                                           std::size_t calibrated_lasers) {
    mrpt::obs::CObservationVelodyneScan obs;
    obs.scan_packets.resize(1);
    auto* bytes = reinterpret_cast<std::uint8_t*>(&obs.scan_packets[0]);
    std::memset(bytes, 0, 1206);
    for (int b = 0; b < 12; ++b) {
        bytes[b * 100] = 0xFF;
        bytes[b * 100 + 1] = 0xEE;
    }
    bytes[4] = 5000 & 0xFF;  // block 0, channel 0: 5000 x 2 mm
    bytes[5] = 5000 >> 8;
    bytes[1204] = 0x37;
    bytes[1205] = product_id;
    obs.calibration.laser_corrections.resize(calibrated_lasers);
    for (auto& l : obs.calibration.laser_corrections) {  // level beams: elevation 0
        l.sinVertCorrection = 0;
        l.cosVertCorrection = 1;
    }
    obs.minRange = 0.5;
    obs.maxRange = 100;
    return obs;
}
}  // namespace

TEST(ObservationToPoints, VelodyneUsesSensorPoseAndObservationCalibration) {
    auto obs = velodyneWithOneReturn(0x22, 16);
    obs.sensorPose = mrpt::poses::CPose3D(0.3, 0, 0.8, 0, 0, 0);
    const ObservationPoints r = observationToRobotPoints(obs);
    ASSERT_TRUE(r.convertible) << r.reason;
    ASSERT_EQ(r.points_robot.size(), 1u);
    // Calibrated elevation 0 (not the datasheet's -15 deg): 10 m straight ahead, then + sensorPose.
    EXPECT_NEAR(r.points_robot[0].x(), 10.3f, 1e-4);
    EXPECT_NEAR(r.points_robot[0].y(), 0.0f, 1e-4);
    EXPECT_NEAR(r.points_robot[0].z(), 0.8f, 1e-4);
}

TEST(ObservationToPoints, VelodyneModelFromCalibrationWhenPacketHasNoId) {
    const auto obs = velodyneWithOneReturn(0x00, 32);  // old HDL-32E firmware: no product id
    const ObservationPoints r = observationToRobotPoints(obs);
    ASSERT_TRUE(r.convertible) << r.reason;
    ASSERT_EQ(r.points_robot.size(), 1u);
    // 32 calibrated lasers -> HDL-32E; channel 0 uses the observation's table (cos=1, sin=0).
    EXPECT_NEAR(r.points_robot[0].z(), 0.0f, 1e-4);
    EXPECT_NEAR(r.points_robot[0].x(), 10.0f, 1e-4);
}

TEST(ObservationToPoints, VelodyneOfUnknownModelIsNotConvertible) {
    const auto obs = velodyneWithOneReturn(0x28, 32);  // VLP-32C product id
    const ObservationPoints r = observationToRobotPoints(obs);
    EXPECT_FALSE(r.convertible);
    EXPECT_NE(r.reason.find("not supported"), std::string::npos) << r.reason;
    EXPECT_TRUE(r.points_robot.empty());
}
