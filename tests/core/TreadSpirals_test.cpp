// core/TreadSpirals: a spiral read from its treads alone about a given axis, on an elevation-map
// cloud built from known wedges. Truth comes from the construction.

#include "core/TreadSpirals.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stairmap {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Six wedges about (2.5, 0.5): nosing k (1..6) at angle 20 + 35 (k - 1) deg, height k 0.17 m
// above the floor at -0.4 m; column 0.12 m, rim 0.95 m; one point per 2 cm of top surface.
constexpr double kFloor = -0.4, kRise = 0.17, kStep = 35.0 * kDeg, kFirst = 20.0 * kDeg;
const Eigen::Vector2d kAxis(2.5, 0.5);

PointCloud wedgesCloud() {
    PointCloud cloud;
    for (double x = kAxis.x() - 2.0; x < kAxis.x() + 2.0; x += 0.02)
        for (double y = kAxis.y() - 2.0; y < kAxis.y() + 2.0; y += 0.02) {
            const Eigen::Vector2d d = Eigen::Vector2d(x, y) - kAxis;
            const double r = d.norm();
            if (r < 0.12) continue;  // the column, unseen
            double a = std::atan2(d.y(), d.x()) - kFirst;
            while (a < 0) a += 2 * M_PI;
            const int k = static_cast<int>(a / kStep);
            const double z = r <= 0.95 && k < 6 ? kFloor + (k + 1) * kRise : kFloor;
            cloud.emplace_back(x, y, z);
        }
    return cloud;
}

SpiralSearchParams searchParams() {
    SpiralSearchParams p;
    p.floor_z = kFloor;
    return p;
}

TEST(TreadSpirals, FindsASpiralFromItsTreadsAloneAboutTheGlimpsedAxis) {
    // No row line at all: every nosing comes from the treads. The axis given is 5 cm off.
    const auto spirals =
        findTreadSpirals(wedgesCloud(), kAxis + Eigen::Vector2d(0.05, 0.0), {}, {}, searchParams());
    ASSERT_EQ(spirals.size(), 1u);
    const SpiralFlight& f = spirals[0];
    EXPECT_LT((f.axis - kAxis).norm(), 0.04);
    EXPECT_NEAR(f.step_angle_rad, kStep, 3.0 * kDeg);
    ASSERT_GE(f.edges.size(), 5u);
    for (std::size_t k = 0; k < f.edges.size(); ++k)
        EXPECT_NEAR(f.edges[k].z, kFloor + (k + 1) * kRise, 0.01) << k;
}

TEST(TreadSpirals, NothingAboutAnAxisWithoutTreads) {
    PointCloud floor;
    for (double x = 0.5; x < 4.5; x += 0.02)
        for (double y = -1.5; y < 2.5; y += 0.02) floor.emplace_back(x, y, kFloor);
    EXPECT_TRUE(findTreadSpirals(floor, kAxis, {}, {}, searchParams()).empty());
    EXPECT_TRUE(findTreadSpirals({}, kAxis, {}, {}, searchParams()).empty());
}

}  // namespace
}  // namespace stairmap
