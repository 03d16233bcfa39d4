// TUM trajectory reading, writing and interpolation against an analytic trajectory.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "RawlogTestUtil.h"
#include "io/rawlog/TumTrajectory.h"

using namespace stairmap::io;

namespace {

// Analytic trajectory: helix x = cos(0.5 t), y = sin(0.5 t), z = 0.1 t, yaw = 0.5 t + pi/2.
Eigen::Isometry3d helix(double t) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(std::cos(0.5 * t), std::sin(0.5 * t), 0.1 * t);
    T.linear() = Eigen::AngleAxisd(0.5 * t + M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    return T;
}

TumTrajectory sampledHelix(double dt, double t_end) {
    TumTrajectory traj;
    for (double t = 0; t <= t_end + 1e-9; t += dt) traj.append(t, helix(t));
    return traj;
}

std::string readError(const std::string& text) {
    std::istringstream in(text);
    try {
        TumTrajectory::read(in, "traj.tum");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(TumTrajectory, ReadsCommentsAndNormalisesQuaternions) {
    std::istringstream in(
        "# timestamp tx ty tz qx qy qz qw\n"
        "\n"
        "1.0 1 2 3 0 0 0 2\n"          // unnormalised identity
        "2.0 4 5 6 0 0 0.7071068 0.7071068\n");
    const TumTrajectory traj = TumTrajectory::read(in, "mem");
    ASSERT_EQ(traj.size(), 2u);
    EXPECT_TRUE(traj.poses()[0].T_world_robot.linear().isApprox(Eigen::Matrix3d::Identity(), 1e-9));
    EXPECT_TRUE(traj.poses()[0].T_world_robot.translation().isApprox(Eigen::Vector3d(1, 2, 3)));
    const Eigen::Vector3d x_axis = traj.poses()[1].T_world_robot.linear().col(0);
    EXPECT_TRUE(x_axis.isApprox(Eigen::Vector3d(0, 1, 0), 1e-6)) << x_axis.transpose();
}

TEST(TumTrajectory, ErrorsNameFileAndLine) {
    EXPECT_EQ(readError("1 0 0 0 0 0 0 1\n2 0 0 0 0 0 1\n"),
              "traj.tum:2: expected 8 numbers 't tx ty tz qx qy qz qw'");
    EXPECT_EQ(readError("# c\n1 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n"),
              "traj.tum:3: timestamp not increasing");
    EXPECT_EQ(readError("1 0 0 0 0 0 0 0\n"), "traj.tum:1: zero quaternion");
    EXPECT_EQ(readError("1 nan 0 0 0 0 0 1\n"), "traj.tum:1: non-finite value");
    EXPECT_EQ(readError("1 0 0 0 0 0 0 1 9\n"), "traj.tum:1: unexpected extra field '9'");
    EXPECT_EQ(readError("1 a 0 0 0 0 0 1\n"),
              "traj.tum:1: expected 8 numbers 't tx ty tz qx qy qz qw', got 'a'");
}

TEST(TumTrajectory, MissingFileNamed) {
    try {
        TumTrajectory::load("/nonexistent/dir/x.tum");
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/x.tum"), std::string::npos);
    }
}

TEST(TumTrajectory, FileRoundTrip) {
    const TumTrajectory traj = sampledHelix(0.1, 2.0);
    const std::string path = stairmap::test::scratchDir() + "/traj.tum";
    traj.save(path);
    const TumTrajectory back = TumTrajectory::load(path);
    ASSERT_EQ(back.size(), traj.size());
    for (std::size_t i = 0; i < traj.size(); ++i) {
        EXPECT_DOUBLE_EQ(back.poses()[i].stamp_s, traj.poses()[i].stamp_s);
        EXPECT_TRUE(back.poses()[i].T_world_robot.isApprox(traj.poses()[i].T_world_robot, 1e-12));
    }
}

TEST(TumTrajectory, InterpolatesAnalyticTrajectory) {
    const TumTrajectory traj = sampledHelix(0.05, 4.0);
    for (double t = 0.013; t < 4.0; t += 0.137) {
        const auto T = traj.poseAt(t);
        ASSERT_TRUE(T.has_value()) << t;
        const Eigen::Isometry3d truth = helix(t);
        // Chord error of linear interpolation on a 1 m radius arc over 0.025 rad: < 1e-4 m.
        EXPECT_LT((T->translation() - truth.translation()).norm(), 1e-4) << "t=" << t;
        const Eigen::AngleAxisd err(T->linear().transpose() * truth.linear());
        EXPECT_LT(std::abs(err.angle()), 1e-9) << "t=" << t;  // slerp is exact for a constant axis
    }
}

TEST(TumTrajectory, SlerpBetweenTwoPoses) {
    TumTrajectory traj;
    Eigen::Isometry3d a = Eigen::Isometry3d::Identity(), b = Eigen::Isometry3d::Identity();
    b.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
    b.translation() = Eigen::Vector3d(2, 0, 0);
    traj.append(10.0, a);
    traj.append(12.0, b);
    const auto T = traj.poseAt(10.5);
    ASSERT_TRUE(T);
    EXPECT_TRUE(T->translation().isApprox(Eigen::Vector3d(0.5, 0, 0)));
    const Eigen::AngleAxisd r(T->linear());
    EXPECT_NEAR(r.angle(), M_PI / 8, 1e-9);
    EXPECT_TRUE(r.axis().isApprox(Eigen::Vector3d::UnitX(), 1e-9));
}

TEST(TumTrajectory, OutsideSpanUsesToleranceThenNothing) {
    const TumTrajectory traj = sampledHelix(0.5, 2.0);
    EXPECT_FALSE(traj.poseAt(-0.2).has_value());
    EXPECT_FALSE(traj.poseAt(2.2).has_value());
    ASSERT_TRUE(traj.poseAt(-0.04, 0.05).has_value());
    EXPECT_TRUE(traj.poseAt(-0.04, 0.05)->isApprox(helix(0.0)));
    EXPECT_TRUE(traj.poseAt(2.04, 0.05)->isApprox(helix(2.0)));
    EXPECT_FALSE(traj.poseAt(2.06, 0.05).has_value());
    EXPECT_FALSE(TumTrajectory().poseAt(0.0).has_value());
    EXPECT_FALSE(traj.poseAt(std::nan("")).has_value());
}

TEST(TumTrajectory, AppendRejectsNonIncreasingTime) {
    TumTrajectory traj;
    traj.append(1.0, Eigen::Isometry3d::Identity());
    EXPECT_THROW(traj.append(1.0, Eigen::Isometry3d::Identity()), std::invalid_argument);
    EXPECT_THROW(traj.append(0.5, Eigen::Isometry3d::Identity()), std::invalid_argument);
}
