// Beam patterns of the sensor presets, and scan noise/dropout statistics (seeded).

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "sim/ScanSimulator.h"
#include "sim/SensorModel.h"

namespace stairmap::sim {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

double elevationDeg(const Eigen::Vector3d& d) { return std::asin(d.z()) * kRadToDeg; }

struct PresetCase {
    const char* model;
    std::size_t beams;
    double lowest_deg;
    double highest_deg;
};

class SensorPresets : public ::testing::TestWithParam<PresetCase> {};

TEST_P(SensorPresets, BeamCountAndElevationsMatchTheDatasheet) {
    const auto c = GetParam();
    SensorParams p = sensorPreset(c.model);
    p.horizontal_resolution_deg = 1.0;
    const auto dirs = beamDirections(p);
    ASSERT_EQ(p.elevations_deg.size(), c.beams);
    ASSERT_EQ(dirs.size(), 360 * c.beams);
    double lo = 90, hi = -90;
    for (const auto& d : dirs) {
        EXPECT_NEAR(d.norm(), 1.0, 1e-12);
        lo = std::min(lo, elevationDeg(d));
        hi = std::max(hi, elevationDeg(d));
    }
    EXPECT_NEAR(lo, c.lowest_deg, 1e-9);
    EXPECT_NEAR(hi, c.highest_deg, 1e-9);
    // Evenly spaced rings.
    const double step = (c.highest_deg - c.lowest_deg) / (c.beams - 1);
    for (std::size_t i = 1; i < c.beams; ++i)
        EXPECT_NEAR(p.elevations_deg[i] - p.elevations_deg[i - 1], step, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Lidars, SensorPresets,
                         ::testing::Values(PresetCase{"vlp16", 16, -15.0, 15.0},
                                           PresetCase{"os1_64", 64, -22.5, 22.5},
                                           PresetCase{"hdl32", 32, -30.67, 10.67}));

TEST(SensorModel, AzimuthStepAndOffset) {
    SensorParams p = vlp16();
    p.horizontal_resolution_deg = 2.0;
    const auto dirs = beamDirections(p, 0.5);
    ASSERT_EQ(dirs.size(), 180u * 16u);
    const double az0 = std::atan2(dirs[0].y(), dirs[0].x()) * kRadToDeg;
    const double az1 = std::atan2(dirs[16].y(), dirs[16].x()) * kRadToDeg;
    EXPECT_NEAR(az0, 0.5, 1e-9);
    EXPECT_NEAR(az1 - az0, 2.0, 1e-9);
}

TEST(SensorModel, DepthCameraFrustum) {
    SensorParams p = depthCamera();
    p.image_width = 40;
    p.image_height = 20;
    const auto dirs = beamDirections(p);
    ASSERT_EQ(dirs.size(), 800u);
    double max_h = 0, max_v = 0;
    for (const auto& d : dirs) {
        EXPECT_GT(d.x(), 0.0);
        max_h = std::max(max_h, std::atan2(std::abs(d.y()), d.x()) * kRadToDeg);
        max_v = std::max(max_v, std::atan2(std::abs(d.z()), d.x()) * kRadToDeg);
    }
    // Pixel centres sit half a pixel inside the 87 x 58 deg frustum.
    EXPECT_LT(max_h, 43.5);
    EXPECT_GT(max_h, 41.0);
    EXPECT_LT(max_v, 29.0);
    EXPECT_GT(max_v, 26.0);
}

TEST(SensorModel, ValidateNamesTheField) {
    SensorParams p = vlp16();
    p.dropout_probability = 1.5;
    try {
        validate(p);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("dropout_probability"), std::string::npos);
    }
    EXPECT_THROW(sensorPreset("vlp99"), std::invalid_argument);
}

/// A wall x = 5 in front of the sensor: range noise along the beam must be zero-mean with the
/// configured standard deviation; dropouts must remove the configured fraction.
TEST(ScanSimulator, RangeNoiseAndDropoutStatistics) {
    Scene scene;
    scene.add(makeAxisAlignedBox({5, -50, -50}, {6, 50, 50}));
    SensorParams p = vlp16();
    p.horizontal_resolution_deg = 0.2;
    p.range_noise_std_m = 0.02;
    p.dropout_probability = 0.1;
    std::mt19937 rng(42);
    const auto points = simulateScan(scene, Eigen::Isometry3d::Identity(), p, rng);
    // Beams with x > 0 hit the wall (half the azimuths, minus the few that graze); compute the
    // expected range per point from its direction.
    std::vector<double> errors;
    for (const auto& q : points) {
        const Eigen::Vector3d d = q.cast<double>().normalized();
        errors.push_back(q.cast<double>().norm() - 5.0 / d.x());
    }
    const double n = static_cast<double>(errors.size());
    const double mean = std::accumulate(errors.begin(), errors.end(), 0.0) / n;
    double var = 0.0;
    for (double e : errors) var += (e - mean) * (e - mean);
    const double std_dev = std::sqrt(var / (n - 1));
    EXPECT_NEAR(mean, 0.0, 0.002);
    EXPECT_NEAR(std_dev, 0.02, 0.001);
    // Beams that reach the wall within max range and inside its extent, counted geometrically.
    double reachable = 0.0;
    for (const auto& d : beamDirections(p)) {
        if (d.x() <= 0) continue;
        const Eigen::Vector3d hit = d * (5.0 / d.x());
        reachable += hit.norm() <= p.max_range_m && std::abs(hit.y()) < 50 && std::abs(hit.z()) < 50;
    }
    EXPECT_NEAR(n / reachable, 0.9, 0.01);
}

TEST(ScanSimulator, SameSeedSameScan) {
    Scene scene;
    scene.add(makeAxisAlignedBox({-10, -10, -1}, {10, 10, 0}));
    SensorParams p = vlp16();
    p.horizontal_resolution_deg = 2.0;
    p.dropout_probability = 0.2;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation().z() = 0.5;
    std::mt19937 a(7), b(7), c(8);
    const auto s1 = simulateScan(scene, T, p, a);
    const auto s2 = simulateScan(scene, T, p, b);
    const auto s3 = simulateScan(scene, T, p, c);
    ASSERT_EQ(s1.size(), s2.size());
    for (std::size_t i = 0; i < s1.size(); ++i) EXPECT_EQ(s1[i], s2[i]);
    EXPECT_TRUE(s1.size() != s3.size() || s1 != s3);
}

}  // namespace
}  // namespace stairmap::sim
