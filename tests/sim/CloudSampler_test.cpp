// Cloud quantisation and sorting (what keeps the bundled gzipped clouds small).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "sim/CloudSampler.h"

namespace stairmap::sim {
namespace {

PointCloud randomCloud(std::size_t n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> coord(-7.0f, 7.0f);
    PointCloud cloud;
    for (std::size_t i = 0; i < n; ++i) cloud.emplace_back(coord(rng), coord(rng), coord(rng));
    return cloud;
}

TEST(CloudQuantization, RoundsToTheGridWithinHalfAStep) {
    const double q = 1.0 / 128.0;
    const PointCloud original = randomCloud(2000, 1);
    PointCloud cloud = original;
    quantizeAndSort(cloud, q, false);
    ASSERT_EQ(cloud.size(), original.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            const double v = cloud[i][k];
            EXPECT_LE(std::abs(v - original[i][k]), 0.5 * q + 1e-6);
            EXPECT_NEAR(v / q, std::round(v / q), 1e-4) << "not on the grid";
        }
    }
}

TEST(CloudQuantization, SortingKeepsThePointsAndOrdersThem) {
    const PointCloud original = randomCloud(1000, 2);
    PointCloud cloud = original;
    quantizeAndSort(cloud, 0.0, true);
    ASSERT_EQ(cloud.size(), original.size());
    for (std::size_t i = 1; i < cloud.size(); ++i) EXPECT_LE(cloud[i - 1].x(), cloud[i].x());
    for (const auto& p : original) EXPECT_NE(std::find(cloud.begin(), cloud.end(), p), cloud.end());
    PointCloud untouched = original;
    quantizeAndSort(untouched, 0.0, false);
    EXPECT_EQ(untouched, original);
}

TEST(CloudQuantization, ValidateRejectsABadQuantum) {
    CloudSampleParams p;
    p.quantum_m = -0.01;
    EXPECT_THROW(validate(p), std::invalid_argument);
    p.quantum_m = 0.1;
    EXPECT_THROW(validate(p), std::invalid_argument);
    p.quantum_m = 0.0078125;
    EXPECT_NO_THROW(validate(p));
}

}  // namespace
}  // namespace stairmap::sim
