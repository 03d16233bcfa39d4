// The fast azimuth binning must give exactly the bins of std::atan2, including points that sit
// on or next to a bin boundary, and its polynomial must stay within its stated error.
#include "core/AzimuthBin.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace stairmap {
namespace {

TEST(AzimuthBin, PolynomialAtan2IsWithinItsStatedError) {
    double worst = 0.0;
    for (int k = 0; k < 200000; ++k) {
        const double a = -M_PI + 2 * M_PI * k / 200000.0;
        const float x = static_cast<float>(3.0 * std::cos(a)),
                    y = static_cast<float>(3.0 * std::sin(a));
        worst = std::max(worst,
                         std::abs(std::remainder(approxAtan2(y, x) - std::atan2(y, x), 2 * M_PI)));
    }
    EXPECT_LT(worst, 3e-6);
    EXPECT_EQ(approxAtan2(0.f, 0.f), 0.f);
}

TEST(AzimuthBin, SameBinsAsStdAtan2ForRandomPoints) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-10.f, 10.f);
    for (int bins : {360, 1800, 3600}) {
        const AzimuthBinner binner(bins);
        for (int k = 0; k < 300000; ++k) {
            const float x = u(rng), y = u(rng);
            ASSERT_EQ(binner(x, y), binner.exact(x, y))
                << "bins " << bins << " at " << x << ", " << y;
        }
    }
}

TEST(AzimuthBin, SameBinsAsStdAtan2OnAndNextToBinBoundaries) {
    const int bins = 1800;
    const AzimuthBinner binner(bins);
    for (int b = 0; b <= bins; ++b) {
        const double boundary = -M_PI + 2 * M_PI * b / bins;
        for (double eps : {-2e-5, -5e-6, -1e-7, 0.0, 1e-7, 5e-6, 2e-5}) {
            for (double r : {0.3, 2.0, 9.5}) {
                const float x = static_cast<float>(r * std::cos(boundary + eps));
                const float y = static_cast<float>(r * std::sin(boundary + eps));
                ASSERT_EQ(binner(x, y), binner.exact(x, y)) << "boundary " << b << " eps " << eps;
            }
        }
    }
}

TEST(AzimuthBin, BinsCoverTheCircleInOrder) {
    const AzimuthBinner binner(1800);
    EXPECT_EQ(binner(-1.f, -1e-7f), 0);  // just past -180 deg
    EXPECT_EQ(binner(1.f, 0.f), 900);    // 0 deg: the middle
    EXPECT_EQ(binner(0.f, 1.f), 1350);   // +90 deg
    EXPECT_EQ(binner(-1.f, 0.f), 1799);  // +180 deg is clamped into the last bin
}

}  // namespace
}  // namespace stairmap
