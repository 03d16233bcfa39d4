// Geometry estimation from known edges, and frame transforms with covariance propagation.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "core/StaircaseGeometry.h"
#include "core/StaircaseTransform.h"

namespace stairmap {
namespace {

/// k nosings of a straight flight: rise h, run d, width w, heading yaw, first nosing centre c0.
Staircase knownFlight(int k, double h, double d, double w, double yaw, Eigen::Vector3d c0) {
    Staircase s;
    const Eigen::Vector3d fwd(std::cos(yaw), std::sin(yaw), 0), left(-std::sin(yaw), std::cos(yaw), 0);
    for (int i = 0; i < k; ++i) {
        const Eigen::Vector3d c = c0 + i * d * fwd + Eigen::Vector3d(0, 0, i * h);
        StairEdge e;
        e.start = c + 0.5 * w * left;
        e.end = c - 0.5 * w * left;
        e.num_points = 40;
        s.steps.push_back(e);
    }
    return s;
}

TEST(StaircaseGeometry, KnownFlightGivesExactParameters) {
    Staircase s = knownFlight(7, 0.17, 0.28, 1.1, 0.7, {2.0, 1.0, -0.33});
    estimateGeometry(s);
    EXPECT_NEAR(s.step_height, 0.17, 1e-9);
    EXPECT_NEAR(s.step_depth, 0.28, 1e-9);
    EXPECT_NEAR(s.step_width, 1.1, 1e-9);
    EXPECT_NEAR(s.slope_rad, std::atan2(0.17, 0.28), 1e-9);
    EXPECT_NEAR(s.heading_rad, 0.7, 1e-9);
    EXPECT_TRUE(s.location.isApprox(Eigen::Vector3d(2.0, 1.0, -0.33)));
}

TEST(StaircaseGeometry, DescendingOrderGivesPositiveRiseAndDownwardHeading) {
    Staircase s = knownFlight(5, -0.18, 0.30, 1.0, -2.0, {0.0, -1.5, -0.5});
    estimateGeometry(s);
    EXPECT_NEAR(s.step_height, 0.18, 1e-9);
    EXPECT_NEAR(s.step_depth, 0.30, 1e-9);
    EXPECT_NEAR(s.heading_rad, -2.0, 1e-9);
}

TEST(StaircaseGeometry, MeanUsesEveryStepNotTwoKDivision) {
    // The paper's formula divides k-1 differences by 2k (h = 0.17 * 6/7 here); a proper estimate
    // must not be biased low.
    Staircase s = knownFlight(4, 0.2, 0.25, 1.0, 0.0, {1, 0, 0});
    estimateGeometry(s);
    EXPECT_NEAR(s.step_height, 0.2, 1e-9);
}

// A far view's last edge read 8 cm short of its nosing (a short, misplaced line), and a put-back
// edge between seen ones placed off its nosing: the run is the median over the seen edges' pairs.
// The least-squares slope of the cumulative spacing read 0.2886 m here.
TEST(StaircaseGeometry, OneMisplacedEdgeDoesNotTiltTheRun) {
    const double yaw = 0.4;
    const Eigen::Vector3d back(-std::cos(yaw), -std::sin(yaw), 0.0);
    Staircase s = knownFlight(6, 0.17, 0.30, 1.2, yaw, {2.0, 0.0, -0.3});
    s.steps[5].start += 0.08 * back;
    s.steps[5].end += 0.08 * back;
    estimateGeometry(s);
    EXPECT_NEAR(s.step_depth, 0.30, 1e-3);
    Staircase put_back = knownFlight(6, 0.17, 0.30, 1.2, yaw, {2.0, 0.0, -0.3});
    put_back.steps[2].num_points = 0;  // interpolated, not measured
    put_back.steps[2].start += 0.10 * back;
    put_back.steps[2].end += 0.10 * back;
    estimateGeometry(put_back);
    EXPECT_NEAR(put_back.step_depth, 0.30, 1e-9);
}

TEST(StaircaseGeometry, MedianPairwiseSlopeFallsBackToLeastSquaresWithFewPairs) {
    const std::vector<double> v{0.0, 1.0, 2.0, 9.0};
    EXPECT_NEAR(medianPairwiseSlope(v, {1, 1, 1, 1}, 3), 3.0, 1e-12);  // 1 1 1 3 4 7: upper middle
    EXPECT_NEAR(medianPairwiseSlope(v, {1, 0, 0, 1}, 3), slopeAgainstIndex(v), 1e-12);  // one pair
    EXPECT_NEAR(medianPairwiseSlope(v, {1, 1, 1, 0}, 3), 1.0, 1e-12);
}

TEST(StaircaseGeometry, WidthIsRobustToPartiallySeenEdges) {
    Staircase s = knownFlight(6, 0.17, 0.28, 1.2, 0.0, {2, 0, 0});
    s.steps[0].end = s.steps[0].centre();  // first edge half seen
    s.steps[4].start = s.steps[4].centre() + 0.1 * (s.steps[4].start - s.steps[4].centre());
    estimateGeometry(s);
    EXPECT_NEAR(s.step_width, 1.2, 1e-9);
    EXPECT_NEAR(s.step_depth, 0.28, 1e-9) << "spacing is perpendicular, not between centres";
}

TEST(StaircaseGeometry, DescendingPartialFirstEdgesKeepLocationOnTheFlightAxis) {
    // Descending flight seen at an angle: the first two edges are cut at one end.
    const double yaw = 0.4;
    const Eigen::Vector3d c0(1.5, -0.5, -0.45);
    Staircase s = knownFlight(6, -0.17, 0.29, 1.1, yaw, c0);
    s.direction = StairDirection::Descending;
    s.steps[0].end = s.steps[0].centre() - 0.1 * (s.steps[0].end - s.steps[0].centre());  // 45 % seen
    s.steps[1].start = s.steps[1].centre() + 0.3 * (s.steps[1].start - s.steps[1].centre());
    estimateGeometry(s);
    EXPECT_NEAR((s.location - c0).norm(), 0.0, 1e-6) << s.location.transpose();
    const Eigen::Vector3d c1 = c0 + 0.29 * Eigen::Vector3d(std::cos(yaw), std::sin(yaw), -0.17 / 0.29);
    EXPECT_NEAR((s.steps[1].centre() - c1).norm(), 0.0, 1e-6);
    EXPECT_NEAR(s.step_width, 1.1, 1e-9);
}

TEST(StaircaseGeometry, PartialEdgesOfAscendingFlightsAreKeptAsObserved) {
    Staircase s = knownFlight(5, 0.17, 0.28, 1.0, 0.0, {2, 0, 0});
    s.steps[0].end = s.steps[0].centre();
    const Eigen::Vector3d seen_centre = s.steps[0].centre();
    estimateGeometry(s);
    EXPECT_NEAR((s.location - seen_centre).norm(), 0.0, 1e-9);
}

TEST(StaircaseGeometry, NoisyEdgesStayWithinMillimetres) {
    std::mt19937 rng(11);
    std::normal_distribution<double> n(0.0, 0.005);
    Staircase s = knownFlight(8, 0.16, 0.30, 1.0, 1.2, {1, 1, 0});
    for (auto& e : s.steps) {
        const Eigen::Vector3d j(n(rng), n(rng), n(rng));
        e.start += j;
        e.end += j;
    }
    estimateGeometry(s);
    EXPECT_NEAR(s.step_height, 0.16, 0.004);
    EXPECT_NEAR(s.step_depth, 0.30, 0.004);
}

TEST(StaircaseGeometry, EmptyStaircaseIsAllZero) {
    Staircase s;
    s.step_height = 3.0;
    estimateGeometry(s);
    EXPECT_EQ(s.step_height, 0.0);
    EXPECT_EQ(s.step_width, 0.0);
}

Eigen::Isometry3d pose(double x, double y, double z, double yaw) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T.translation() << x, y, z;
    return T;
}

TEST(StaircaseTransform, RoundTripRestoresEverything) {
    Staircase s = knownFlight(5, 0.17, 0.28, 1.1, 0.4, {2.0, 1.0, -0.33});
    for (auto& e : s.steps) e.cov_rho_theta << 4e-5, 1e-5, 1e-5, 2e-4;
    estimateGeometry(s);
    const Eigen::Isometry3d T_world_robot = pose(5.0, -3.0, 1.2, 2.5);
    const Staircase w = transformStaircase(s, T_world_robot);
    EXPECT_NEAR(std::remainder(w.heading_rad - (0.4 + 2.5), 2 * M_PI), 0.0, 1e-12);
    EXPECT_TRUE(w.location.isApprox(T_world_robot * s.location));
    EXPECT_NEAR(w.step_height, s.step_height, 1e-12);
    const Staircase back = transformStaircase(w, T_world_robot.inverse());
    for (std::size_t i = 0; i < s.steps.size(); ++i) {
        EXPECT_TRUE(back.steps[i].start.isApprox(s.steps[i].start, 1e-12));
        EXPECT_TRUE(back.steps[i].cov_rho_theta.isApprox(s.steps[i].cov_rho_theta, 1e-9))
            << back.steps[i].cov_rho_theta << "\nvs\n" << s.steps[i].cov_rho_theta;
    }
    EXPECT_NEAR(std::remainder(back.heading_rad - s.heading_rad, 2 * M_PI), 0.0, 1e-12);
}

TEST(StaircaseTransform, CovarianceMatchesMonteCarloPropagation) {
    // Sample lines from N(mean, C) in frame A, map them exactly to frame B, compare covariances.
    StairEdge e;
    e.start << 1.0, 2.0, 0.0;
    e.end << 2.0, 1.5, 0.0;
    e.cov_rho_theta << 1e-4, -2e-5, -2e-5, 4e-4;
    const Eigen::Vector2d rt = e.rhoTheta();
    const double yaw = 0.9;
    const Eigen::Vector2d t(3.0, -1.0);
    const Eigen::Matrix2d predicted = transformLineCovariance(e.cov_rho_theta, rt, yaw, t);

    std::mt19937 rng(5);
    std::normal_distribution<double> n01(0.0, 1.0);
    const Eigen::Matrix2d L = e.cov_rho_theta.llt().matrixL();
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
    const int N = 20000;
    std::vector<Eigen::Vector2d> samples;
    for (int i = 0; i < N; ++i) {
        const Eigen::Vector2d x = rt + L * Eigen::Vector2d(n01(rng), n01(rng));
        const double th = x.y() + yaw;
        double rho = x.x() + t.dot(Eigen::Vector2d(std::cos(th), std::sin(th)));
        samples.emplace_back(rho, th);
        mean += samples.back() / N;
    }
    for (const auto& s : samples) second += (s - mean) * (s - mean).transpose() / (N - 1);
    EXPECT_NEAR(second(0, 0), predicted(0, 0), 0.05 * predicted(0, 0));
    EXPECT_NEAR(second(1, 1), predicted(1, 1), 0.05 * predicted(1, 1));
    EXPECT_NEAR(second(0, 1), predicted(0, 1), 0.05 * std::sqrt(predicted(0, 0) * predicted(1, 1)));
}

}  // namespace
}  // namespace stairmap
