// Streaming rawlog input: both formats, pose sources, skipped/unsupported counting, bad files.
#include <gtest/gtest.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationRotatingScan.h>

#include <cmath>
#include <fstream>
#include <random>

#include "RawlogTestUtil.h"
#include "io/rawlog/RawlogScanSource.h"

using namespace stairmap;
using namespace stairmap::io;
using namespace stairmap::test;
using mrpt::poses::CPose3D;

namespace {

std::vector<Scan> readAll(RawlogScanSource& src) {
    std::vector<Scan> scans;
    while (auto s = src.next()) scans.push_back(std::move(*s));
    return scans;
}

Eigen::Vector3d worldPoint(const Scan& s, std::size_t i) {
    return s.T_world_robot * s.points_robot.at(i).cast<double>();
}

const CPose3D kSensorOnRobot(0, 0, 0.5, 0, 0, 0);  // sensor 0.5 m above the robot origin

}  // namespace

class RawlogCompression : public ::testing::TestWithParam<bool> {};

TEST_P(RawlogCompression, ObservationsOnlyFrameMath) {
    const std::string path = scratchDir() + "/obs.rawlog";
    {
        RawlogWriter w(path, GetParam());
        for (int i = 0; i < 3; ++i) {
            w << *makePoseObs(i, CPose3D(10 + i, 0, 0, 0, 0, 0));
            w << *makeCloudObs(i, kSensorOnRobot, {{1, 0, 0}});
        }
    }
    RawlogScanSource src(path);
    const auto scans = readAll(src);
    ASSERT_EQ(scans.size(), 3u);
    for (int i = 0; i < 3; ++i) {
        // Robot at x=10+i, sensor 0.5 up, sensor point (1,0,0) -> world (11+i, 0, 0.5).
        EXPECT_TRUE(worldPoint(scans[i], 0).isApprox(Eigen::Vector3d(11 + i, 0, 0.5), 1e-6))
            << worldPoint(scans[i], 0).transpose();
        EXPECT_EQ(scans[i].sensor_label, "lidar");
        EXPECT_NEAR(scans[i].stamp_s, i, 1e-6);
        EXPECT_EQ(scans[i].index, std::size_t(i));
    }
    EXPECT_EQ(src.stats().scans_read, 3u);
    EXPECT_EQ(src.stats().scans_emitted, 3u);
    EXPECT_EQ(src.stats().robot_poses_read, 3u);
    EXPECT_EQ(src.stats().points_emitted, 3u);
    EXPECT_TRUE(src.stats().unsupported.empty());
}

TEST_P(RawlogCompression, ActionsAndFramesComposeIncrements) {
    const std::string path = scratchDir() + "/actions.rawlog";
    {
        RawlogWriter w(path, GetParam());
        for (int i = 0; i < 4; ++i) {
            // Each step: 1 m forward then turn +90 deg: a square path.
            w << makeMove3D(i == 0 ? CPose3D() : CPose3D(1, 0, 0, M_PI / 2, 0, 0));
            mrpt::obs::CSensoryFrame sf;
            sf.insert(makeCloudObs(i, kSensorOnRobot, {{1, 0, 0}}));
            w << sf;
        }
    }
    RawlogScanSource src(path);
    const auto scans = readAll(src);
    ASSERT_EQ(scans.size(), 4u);
    const Eigen::Vector3d expected_robot[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (int i = 0; i < 4; ++i) {
        EXPECT_LT((scans[i].T_world_robot.translation() - expected_robot[i]).norm(), 1e-9)
            << i << ": " << scans[i].T_world_robot.translation().transpose();
    }
    // Scan 2: robot at (1,1) heading 180 deg (two turns): sensor point (1,0,0) -> (0,1,0.5).
    EXPECT_TRUE(worldPoint(scans[2], 0).isApprox(Eigen::Vector3d(0, 1, 0.5), 1e-6))
        << worldPoint(scans[2], 0).transpose();
    EXPECT_EQ(src.stats().odometry_read, 4u);
}

TEST_P(RawlogCompression, FrameWithoutActionIsNotDropped) {
    const std::string path = scratchDir() + "/frames.rawlog";
    {
        RawlogWriter w(path, GetParam());
        for (int i = 0; i < 3; ++i) {
            mrpt::obs::CSensoryFrame sf;
            sf.insert(makePoseObs(i, CPose3D(i, 0, 0, 0, 0, 0)));
            sf.insert(makeCloudObs(i, kSensorOnRobot, {{1, 0, 0}, {2, 0, 0}}));
            w << sf;
        }
    }
    RawlogScanSource src(path);
    const auto scans = readAll(src);
    ASSERT_EQ(scans.size(), 3u);
    EXPECT_TRUE(worldPoint(scans[2], 1).isApprox(Eigen::Vector3d(4, 0, 0.5), 1e-6));
}

TEST(RawlogScanSource, OdometryPrefers3DAndFallsBackTo2D) {
    const std::string path = scratchDir() + "/odometry.rawlog";
    {
        RawlogWriter w(path, false);
        for (int i = 0; i < 3; ++i) {
            mrpt::obs::CActionCollection acts;
            mrpt::obs::CActionRobotMovement2D move2d;
            mrpt::obs::CActionRobotMovement2D::TMotionModelOptions opts;
            move2d.computeFromOdometry(mrpt::poses::CPose2D(2.0, 0, 0), opts);  // 2 m per step
            acts.insert(move2d);
            if (i < 2) {  // the same step also as a 3D movement of 1 m: must win over the 2D one
                mrpt::obs::CActionRobotMovement3D move3d;
                move3d.poseChange.mean = CPose3D(1, 0, 0, 0, 0, 0);
                acts.insert(move3d);
            }
            w << acts;
            mrpt::obs::CSensoryFrame sf;
            sf.insert(makeCloudObs(i, kSensorOnRobot, {{1, 0, 0}}));
            w << sf;
        }
    }
    RawlogScanSource src(path);
    const auto scans = readAll(src);
    ASSERT_EQ(scans.size(), 3u);
    EXPECT_NEAR(scans[0].T_world_robot.translation().x(), 1.0, 1e-6);
    EXPECT_NEAR(scans[1].T_world_robot.translation().x(), 2.0, 1e-6);
    EXPECT_NEAR(scans[2].T_world_robot.translation().x(), 4.0, 1e-6);  // + 2 m from 2D odometry
    EXPECT_EQ(src.stats().odometry_read, 3u);
}

INSTANTIATE_TEST_SUITE_P(PlainAndGz, RawlogCompression, ::testing::Values(false, true),
                         [](const auto& param_info) { return param_info.param ? "gz" : "plain"; });

TEST(RawlogScanSource, RobotPoseAfterScanAndNearestInTime) {
    const std::string path = scratchDir() + "/after.rawlog";
    {
        RawlogWriter w(path, false);
        w << *makeCloudObs(1.0, kSensorOnRobot, {{1, 0, 0}});   // pose comes after
        w << *makePoseObs(0.98, CPose3D(5, 0, 0, 0, 0, 0));     // 20 ms off
        w << *makePoseObs(1.01, CPose3D(7, 0, 0, 0, 0, 0));     // 10 ms off: nearest
        w << *makePoseObs(2.0, CPose3D(9, 0, 0, 0, 0, 0));
        w << *makeCloudObs(2.0, kSensorOnRobot, {{1, 0, 0}});   // pose came before
    }
    RawlogScanSource src(path);
    const auto scans = readAll(src);
    ASSERT_EQ(scans.size(), 2u);
    EXPECT_NEAR(scans[0].T_world_robot.translation().x(), 7.0, 1e-9);
    EXPECT_NEAR(scans[1].T_world_robot.translation().x(), 9.0, 1e-9);
}

TEST(RawlogScanSource, ScansWithoutPoseAreSkippedAndCounted) {
    const std::string path = scratchDir() + "/nopose.rawlog";
    {
        RawlogWriter w(path, false);
        w << *makePoseObs(0.0, CPose3D(1, 0, 0, 0, 0, 0));
        w << *makeCloudObs(0.0, kSensorOnRobot, {{1, 0, 0}});
        w << *makeCloudObs(5.0, kSensorOnRobot, {{1, 0, 0}});  // no pose near t=5
        w << *makeCloudObs(6.0, kSensorOnRobot, {{1, 0, 0}});
        w << *makePoseObs(10.0, CPose3D(2, 0, 0, 0, 0, 0));
    }
    RawlogScanSource src(path);
    const auto scans = readAll(src);
    ASSERT_EQ(scans.size(), 1u);
    EXPECT_EQ(src.stats().scans_read, 3u);
    EXPECT_EQ(src.stats().skipped_no_pose, 2u);
    ASSERT_EQ(src.messages().size(), 1u);  // reported once
    EXPECT_NE(src.messages()[0].find("without robot pose"), std::string::npos);
}

TEST(RawlogScanSource, UnsupportedTypesCountedAndReportedOnce) {
    const std::string path = scratchDir() + "/unsupported.rawlog";
    {
        RawlogWriter w(path, false);
        for (int i = 0; i < 3; ++i) {
            mrpt::obs::CObservationRotatingScan rot;
            rot.timestamp = stamp(i);
            w << rot;
            mrpt::obs::CObservation2DRangeScan scan2d;
            scan2d.timestamp = stamp(i);
            w << scan2d;
            w << *makePoseObs(i, CPose3D());
            w << *makeCloudObs(i, kSensorOnRobot, {{1, 0, 0}});
        }
    }
    RawlogScanSource src(path);
    std::vector<std::string> printed;
    src.setWarningHandler([&](const std::string& m) { printed.push_back(m); });
    EXPECT_EQ(readAll(src).size(), 3u);
    const auto& unsupported = src.stats().unsupported;
    ASSERT_EQ(unsupported.size(), 2u);
    EXPECT_EQ(unsupported.at("mrpt::obs::CObservationRotatingScan"), 3u);
    EXPECT_EQ(unsupported.at("mrpt::obs::CObservation2DRangeScan"), 3u);
    EXPECT_EQ(printed.size(), 2u);
    EXPECT_EQ(src.messages(), printed);
    EXPECT_NE(printed[0].find("CObservationRotatingScan"), std::string::npos);
    EXPECT_NE(printed[0].find(path), std::string::npos);
}

TEST(RawlogScanSource, SensorLabelFilter) {
    const std::string path = scratchDir() + "/labels.rawlog";
    {
        RawlogWriter w(path, false);
        w << *makePoseObs(0, CPose3D());
        w << *makeCloudObs(0, kSensorOnRobot, {{1, 0, 0}}, "lidar");
        w << *makeCloudObs(0, kSensorOnRobot, {{1, 0, 0}, {2, 0, 0}}, "depth_cam");
    }
    RawlogSourceParams params;
    params.sensor_label = "depth_cam";
    RawlogScanSource src(path, params);
    const auto scans = readAll(src);
    ASSERT_EQ(scans.size(), 1u);
    EXPECT_EQ(scans[0].sensor_label, "depth_cam");
    EXPECT_EQ(scans[0].points_robot.size(), 2u);
    EXPECT_EQ(src.stats().skipped_label, 1u);
}

TEST(RawlogScanSource, TumTrajectoryIsPreferredAndInterpolated) {
    const std::string path = scratchDir() + "/tum.rawlog";
    {
        RawlogWriter w(path, false);
        for (double t : {0.25, 1.5, 2.75, 9.0}) {
            w << *makePoseObs(t, CPose3D(100, 100, 0, 0, 0, 0));  // must be ignored
            w << *makeCloudObs(t, kSensorOnRobot, {{1, 0, 0}});
        }
    }
    // Analytic trajectory: x = t, yaw = 0.2 t, sampled every 0.5 s on [0, 3].
    TumTrajectory traj;
    for (int k = 0; k <= 6; ++k) {
        const double t = 0.5 * k;
        Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
        T.linear() = Eigen::AngleAxisd(0.2 * t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        T.translation() = Eigen::Vector3d(t, 0, 0);
        traj.append(t, T);
    }
    RawlogScanSource src(path, {}, traj);
    const auto scans = readAll(src);
    ASSERT_EQ(scans.size(), 3u);  // t = 9 is outside [0, 3]
    EXPECT_EQ(src.stats().skipped_no_pose, 1u);
    const double times[3] = {0.25, 1.5, 2.75};
    for (int i = 0; i < 3; ++i) {
        const double t = times[i], yaw = 0.2 * t;
        const Eigen::Vector3d expected(t + std::cos(yaw), std::sin(yaw), 0.5);
        EXPECT_TRUE(worldPoint(scans[i], 0).isApprox(expected, 1e-6))
            << "t=" << t << " got " << worldPoint(scans[i], 0).transpose();
    }
}
