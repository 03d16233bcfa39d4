// Frame math of the one observation -> robot-frame points conversion.
#include <gtest/gtest.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationRotatingScan.h>
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <cmath>
#include <limits>

#include "io/ObservationToPoints.h"

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
