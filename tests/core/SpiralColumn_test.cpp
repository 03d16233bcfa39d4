// The column of a spiral measured on its own points: a hand-made column seen from one side, the
// treads' inner ends at its surface, and an axis guessed a few cm off.
#include "core/SpiralColumn.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace stairmap {
namespace {

const Eigen::Vector2d kCentre(2.0, 1.0);  // [m] the column's axis
constexpr double kRadius = 0.15;          // [m]

/// The column's surface on the half facing the robot (at the origin), 5 mm noise, from z = 0 to
/// 1.5 m, and wedge treads from the column outwards every 0.17 m up, turning 25 deg a step.
PointCloud columnAndTreads() {
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.005);
    PointCloud c;
    const double towards_robot = std::atan2(-kCentre.y(), -kCentre.x());
    for (double z = 0.0; z < 1.5; z += 0.05)
        for (double a = -80.0; a <= 80.0; a += 4.0) {
            const double phi = towards_robot + a * M_PI / 180.0;
            const double r = kRadius + noise(rng);
            c.emplace_back(float(kCentre.x() + r * std::cos(phi)),
                           float(kCentre.y() + r * std::sin(phi)), float(z));
        }
    for (int k = 0; k < 8; ++k) {
        const double phi0 = k * 25.0 * M_PI / 180.0, z = 0.17 * (k + 1);
        for (double r = kRadius + 0.01; r < 1.0; r += 0.03)
            for (double a = 0.0; a < 25.0; a += 3.0) {
                const double phi = phi0 + a * M_PI / 180.0;
                c.emplace_back(float(kCentre.x() + r * std::cos(phi)),
                               float(kCentre.y() + r * std::sin(phi)), float(z));
            }
    }
    return c;
}

TEST(SpiralColumn, TheRadiusAndCentreOfAColumnSeenFromOneSide) {
    const Eigen::Vector2d guess = kCentre + Eigen::Vector2d(0.03, -0.02);  // the fitted axis, off
    const auto col = fitSpiralColumn(columnAndTreads(), guess, -0.05, 1.6, 0.35);
    ASSERT_TRUE(col.has_value());
    EXPECT_NEAR(col->radius_m, kRadius, 0.005);
    // The centre is held less tightly along the line of sight (half the column is seen).
    EXPECT_NEAR((col->centre - kCentre).norm(), 0.0, 0.02);
}

TEST(SpiralColumn, TooFewSectorsOrACentreFarFromTheAxisGiveNothing) {
    EXPECT_FALSE(fitSpiralColumn(PointCloud{}, kCentre, -1.0, 2.0, 0.35).has_value());
    PointCloud three_sectors;
    for (double z = 0.0; z < 1.0; z += 0.1)
        for (double phi : {0.0, 2.0, 4.0})
            three_sectors.emplace_back(float(kCentre.x() + kRadius * std::cos(phi)),
                                       float(kCentre.y() + kRadius * std::sin(phi)), float(z));
    EXPECT_FALSE(fitSpiralColumn(three_sectors, kCentre, -1.0, 2.0, 0.35).has_value());
    // An axis 0.2 m off: the circle's centre lies farther than max_centre_shift_m from it.
    EXPECT_FALSE(
        fitSpiralColumn(columnAndTreads(), kCentre + Eigen::Vector2d(0.2, 0.0), -0.05, 1.6, 0.6)
            .has_value());
}

TEST(SpiralColumn, NonFinitePointsAndPointsOutsideTheHeightsAreSkipped) {
    PointCloud c = columnAndTreads();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    c.emplace_back(nan, nan, nan);
    c.emplace_back(float(kCentre.x() + 0.01), float(kCentre.y()), nan);
    c.emplace_back(float(kCentre.x() + 0.02), float(kCentre.y()), 5.0f);  // above the heights
    const auto col = fitSpiralColumn(c, kCentre, -0.05, 1.6, 0.35);
    ASSERT_TRUE(col.has_value());
    EXPECT_NEAR(col->radius_m, kRadius, 0.01);
}

}  // namespace
}  // namespace stairmap
