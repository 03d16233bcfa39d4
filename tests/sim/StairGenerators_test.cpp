// Generated stairs: the solids are where the ground truth says (rays probe tread tops and risers),
// and the nosings follow the documented convention.

#include <gtest/gtest.h>

#include <cmath>

#include "sim/BuildingGenerator.h"
#include "sim/NegativeGenerators.h"
#include "sim/StairGenerators.h"

namespace stairmap::sim {
namespace {

const Eigen::Vector3d kDown(0, 0, -1);

double dropHeight(const Scene& scene, double x, double y) {
    const auto t = scene.castRay({{x, y, 20.0}, kDown}, 100.0);
    return t ? 20.0 - *t : -1e9;
}

TEST(StairGenerators, StraightFlightTreadsAndNosings) {
    Scene scene;
    StraightStairParams p;
    p.num_risers = 5;
    p.rise_m = 0.2;
    p.run_m = 0.3;
    p.width_m = 1.0;
    p.origin = {1.0, 2.0, 0.5};
    p.heading_deg = 90.0;  // ascends towards +y
    addStraightStair(scene, p);
    const auto& truth = scene.truth().staircases.at(0);
    ASSERT_EQ(truth.nosings.size(), 5u);
    EXPECT_DOUBLE_EQ(truth.bottom_z, 0.5);
    EXPECT_DOUBLE_EQ(truth.top_z, 1.5);
    for (int i = 1; i <= 5; ++i) {
        const auto& n = truth.nosings[i - 1];
        // Nosing i: (i-1) runs up the flight, at the height of tread i, spanning the width along x.
        EXPECT_NEAR(n.centre().x(), 1.0, 1e-9);
        EXPECT_NEAR(n.centre().y(), 2.0 + (i - 1) * 0.3, 1e-9);
        EXPECT_NEAR(n.centre().z(), 0.5 + i * 0.2, 1e-9);
        EXPECT_NEAR((n.end - n.start).norm(), 1.0, 1e-9);
        // Just behind each nosing the tread top is at the nosing height; just before it, one rise lower.
        EXPECT_NEAR(dropHeight(scene, 1.0, n.centre().y() + 0.05), n.centre().z(), 1e-9) << "tread " << i;
        if (i > 1) {
            EXPECT_NEAR(dropHeight(scene, 1.0, n.centre().y() - 0.05), n.centre().z() - 0.2, 1e-9);
        }
    }
}

TEST(StairGenerators, HollowStairHasOpenRisers) {
    Scene scene;
    StraightStairParams p;
    p.open_risers = true;
    p.solid_landing = false;
    p.wall_left = p.wall_right = false;
    p.num_risers = 4;
    p.rise_m = 0.2;
    p.run_m = 0.3;
    addStraightStair(scene, p);
    // A horizontal ray below tread 2 (between tread 1 top at 0.2 and tread 2 bottom at 0.36) passes
    // through the riser gap and first meets the side of tread 1? No: it starts above tread 1 and
    // travels along x at z = 0.3, so it hits tread 2's front face only if risers were closed.
    const auto t = scene.castRay({{-1.0, 0.0, 0.3}, Eigen::Vector3d::UnitX()}, 100.0);
    EXPECT_FALSE(t.has_value() && *t < 1.0 + 0.3 + 0.01) << "closed riser found at t=" << *t;
    // Tread tops are still at the nosing heights.
    EXPECT_NEAR(dropHeight(scene, 0.45, 0.0), 0.4, 1e-9);
}

TEST(StairGenerators, SpiralNosingsAreRadialAtTreadHeights) {
    Scene scene;
    SpiralStairParams p;
    p.num_risers = 6;
    p.rise_m = 0.2;
    p.column_radius_m = 0.1;
    p.outer_radius_m = 1.1;
    p.step_angle_deg = 30.0;
    addSpiralStair(scene, p);
    const auto& truth = scene.truth().staircases.at(0);
    ASSERT_EQ(truth.nosings.size(), 6u);
    EXPECT_NEAR(truth.width_m, 1.0, 1e-12);
    EXPECT_NEAR(truth.run_m, 2 * 0.6 * std::sin(M_PI / 12), 1e-12);
    for (int i = 1; i <= 6; ++i) {
        const double a = (i - 1) * M_PI / 6;
        const auto& n = truth.nosings[i - 1];
        EXPECT_NEAR(n.start.x(), 0.1 * std::cos(a), 1e-9);
        EXPECT_NEAR(n.end.y(), 1.1 * std::sin(a), 1e-9);
        EXPECT_NEAR(n.start.z(), 0.2 * i, 1e-12);
        // Probe the tread half a step past its nosing at mid radius.
        const double b = a + M_PI / 12;
        EXPECT_NEAR(dropHeight(scene, 0.6 * std::cos(b), 0.6 * std::sin(b)), 0.2 * i, 1e-9);
    }
}

TEST(StairGenerators, DebrisLiesOnTheTreads) {
    Scene plain, cluttered;
    StraightStairParams p;
    addStraightStair(plain, p);
    p.debris_count = 12;
    addStraightStair(cluttered, p);
    EXPECT_EQ(cluttered.primitives().size(), plain.primitives().size() + 12);
    for (std::size_t k = plain.primitives().size(); k < cluttered.primitives().size(); ++k) {
        const Aabb box = boundingBox(cluttered.primitives()[k]);
        const double rel = box.min.z() / p.rise_m;  // sits on a tread: bottom at a multiple of rise
        EXPECT_NEAR(rel, std::round(rel), 1e-9);
        EXPECT_LE(box.max.z() - box.min.z(), p.debris_max_size_m + 1e-9);
    }
}

TEST(StairGenerators, TwoFloorBuildingTruth) {
    Scene scene;
    BuildingParams p;
    addTwoFloorBuilding(scene, p);
    ASSERT_EQ(scene.truth().staircases.size(), 2u);
    ASSERT_EQ(scene.truth().floor_heights.size(), 2u);
    EXPECT_DOUBLE_EQ(scene.truth().floor_heights[1], 3.0);
    for (const auto& s : scene.truth().staircases) {
        EXPECT_EQ(s.num_risers, 16);
        EXPECT_NEAR(s.nosings.back().centre().z(), 3.0, 1e-9);
        // The upper floor continues right behind the top nosing.
        const Eigen::Vector3d dir = (s.nosings.back().centre() - s.nosings.front().centre()).normalized();
        const Eigen::Vector3d probe = s.nosings.back().centre() + 0.5 * Eigen::Vector3d(dir.x(), dir.y(), 0).normalized();
        EXPECT_NEAR(dropHeight(scene, probe.x(), probe.y()), 3.0, 1e-9) << s.name;
    }
}

TEST(StairGenerators, NegativesHaveNoStaircaseAndRejectBadTypes) {
    for (const char* type : {"room", "ramp", "curb", "stage", "bleachers"}) {
        Scene scene;
        NegativeParams p;
        p.type = type;
        addNegative(scene, p);
        EXPECT_TRUE(scene.truth().staircases.empty()) << type;
        EXPECT_GT(scene.primitives().size(), 1u) << type;
    }
    Scene ramp;
    NegativeParams p;
    p.type = "ramp";
    p.ramp_slope_deg = 10.0;
    addNegative(ramp, p);
    EXPECT_NEAR(dropHeight(ramp, 2.0, 0.0), 2.0 * std::tan(10.0 * M_PI / 180), 1e-9);
    Scene bad;
    p.type = "pyramid";
    EXPECT_THROW(addNegative(bad, p), std::invalid_argument);
    p.type = "bleachers";
    p.bleacher_rise_m = 0.2;  // would be a staircase
    EXPECT_THROW(addNegative(bad, p), std::invalid_argument);
}

}  // namespace
}  // namespace stairmap::sim
