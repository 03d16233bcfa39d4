#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/FloorNoise.h"

namespace stairmap {
namespace {

constexpr double kFloor = -0.5;

/// Floor points at `count` random places of the ring [r_lo, r_hi] with Gaussian height noise.
void addFloorRing(PointCloud& cloud, double r_lo, double r_hi, double sigma, int count,
                  unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> radius(r_lo, r_hi), angle(-M_PI, M_PI);
    std::normal_distribution<double> noise(0.0, sigma);
    for (int i = 0; i < count; ++i) {
        const double r = radius(rng), a = angle(rng);
        cloud.emplace_back(static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)),
                           static_cast<float>(kFloor + noise(rng)));
    }
}

TEST(FloorNoise, MeasuresTheGaussianSigmaOfTheFloorInTheRing) {
    for (double sigma : {0.004, 0.01, 0.015}) {
        PointCloud cloud;
        addFloorRing(cloud, 2.5, 4.5, sigma, 20000, 7);
        EXPECT_NEAR(floorHeightNoise(cloud, kFloor), sigma, 0.1 * sigma) << "sigma " << sigma;
    }
}

TEST(FloorNoise, OnlyTheRingsFloorPointsCount) {
    PointCloud cloud;
    addFloorRing(cloud, 2.5, 4.5, 0.003, 5000, 1);
    addFloorRing(cloud, 0.5, 2.4, 0.03, 5000, 2);  // near the robot: noisier, not in the ring
    addFloorRing(cloud, 4.6, 8.0, 0.03, 5000, 3);  // beyond it
    for (int i = 0; i < 2000; ++i)  // a wall and a table in the ring: not floor
        cloud.emplace_back(3.0f, -1.0f + 0.001f * i, static_cast<float>(kFloor + 0.06 + 0.001 * i));
    EXPECT_NEAR(floorHeightNoise(cloud, kFloor), 0.003, 0.0005);
}

TEST(FloorNoise, TooFewFloorPointsOrNonFiniteOnesGiveNoMeasurement) {
    PointCloud cloud;
    addFloorRing(cloud, 2.5, 4.5, 0.01, 49, 4);
    EXPECT_EQ(floorHeightNoise(cloud, kFloor), 0.0);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (int i = 0; i < 100; ++i) cloud.emplace_back(nan, 3.0f, static_cast<float>(kFloor));
    for (int i = 0; i < 100; ++i) cloud.emplace_back(3.0f, 0.0f, nan);
    EXPECT_EQ(floorHeightNoise(cloud, kFloor), 0.0);
    EXPECT_EQ(floorHeightNoise(PointCloud{}, kFloor), 0.0);
}

}  // namespace
}  // namespace stairmap
