// Analytic ray intersections against hand-computed distances.

#include <gtest/gtest.h>

#include <cmath>

#include "sim/Primitives.h"
#include "sim/Scene.h"

namespace stairmap::sim {
namespace {

Ray ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) {
    return {origin, direction.normalized()};
}

TEST(Primitives, AxisAlignedBoxFrontFaceAtKnownDistance) {
    const Box box = makeAxisAlignedBox({2, -1, 0}, {3, 1, 1});
    const auto t = intersect(box, ray({0, 0, 0.5}, {1, 0, 0}));
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 2.0, 1e-12);
    EXPECT_FALSE(intersect(box, ray({0, 0, 0.5}, {-1, 0, 0})));  // pointing away
    EXPECT_FALSE(intersect(box, ray({0, 0, 1.5}, {1, 0, 0})));   // passes above
}

TEST(Primitives, ObliqueRayOntoTopFace) {
    // From (0,0,2) towards (1,0,-1)/sqrt2: reaches z = 1 after travelling 1 in x, i.e. t = sqrt(2).
    const Box box = makeAxisAlignedBox({0.5, -1, 0}, {3, 1, 1});
    const auto t = intersect(box, ray({0, 0, 2}, {1, 0, -1}));
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, std::sqrt(2.0), 1e-12);
}

TEST(Primitives, RotatedBoxUsesItsOwnAxes) {
    // A unit cube rotated 45 deg about z, centred at (5,0,0): its corner faces the ray along x at
    // distance 5 - sqrt(2)/2.
    Box box;
    box.half_extents = {0.5, 0.5, 0.5};
    box.T_world_box = Eigen::Translation3d(5, 0, 0) * Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ());
    const auto t = intersect(box, ray({0, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 5.0 - std::sqrt(0.5), 1e-9);
}

TEST(Primitives, RayStartingInsideABoxReportsTheExit) {
    const Box box = makeAxisAlignedBox({-1, -1, -1}, {1, 1, 1});
    const auto t = intersect(box, ray({0, 0, 0}, {0, 1, 0}));
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 1.0, 1e-12);
}

TEST(Primitives, CylinderSideAndCap) {
    const Cylinder cyl{{4, 0}, 0.5, 0.0, 2.0};
    auto t = intersect(cyl, ray({0, 0, 1}, {1, 0, 0}));
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 3.5, 1e-12);
    t = intersect(cyl, ray({4.2, 0, 5}, {0, 0, -1}));  // straight down onto the top cap
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 3.0, 1e-12);
    EXPECT_FALSE(intersect(cyl, ray({0, 0.6, 1}, {1, 0, 0})));  // tangent-free miss
    EXPECT_FALSE(intersect(cyl, ray({0, 0, 2.5}, {1, 0, 0})));  // above the cap
}

TEST(Primitives, HelicalWedgeOuterSurfaceRadialFaceAndTop) {
    HelicalWedge w;
    w.centre_xy = {0, 0};
    w.inner_radius = 0.2;
    w.outer_radius = 1.0;
    w.angle_start = 0.0;
    w.angle_span = M_PI / 2;  // first quadrant
    w.z_min = 0.0;
    w.z_max = 0.2;
    // Along the 45 deg diagonal from far away: hits the outer cylinder at r = 1.
    const Eigen::Vector3d dir = Eigen::Vector3d(-1, -1, 0).normalized();
    auto t = intersect(w, ray({3, 3, 0.1}, dir));
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, std::sqrt(18.0) - 1.0, 1e-9);
    // From y < 0 towards +y at x = 0.5: hits the radial face at angle 0 (the plane y = 0).
    t = intersect(w, ray({0.5, -2, 0.1}, {0, 1, 0}));
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 2.0, 1e-9);
    // Straight down at r = 0.6 inside the sector: hits the top at z = 0.2.
    t = intersect(w, ray({0.6 * std::cos(0.7), 0.6 * std::sin(0.7), 1.0}, {0, 0, -1}));
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 0.8, 1e-9);
    // Outside the sector (third quadrant) and inside the hole: misses.
    EXPECT_FALSE(intersect(w, ray({-0.5, -0.5, 1.0}, {0, 0, -1})));
    EXPECT_FALSE(intersect(w, ray({0.05, 0.05, 1.0}, {0, 0, -1})));
}

TEST(Primitives, SceneReturnsTheNearestHitWithinRange) {
    Scene scene;
    scene.add(makeAxisAlignedBox({5, -1, -1}, {6, 1, 1}));
    scene.add(makeAxisAlignedBox({3, -1, -1}, {3.1, 1, 1}));
    scene.add(Cylinder{{8, 0}, 0.5, -1, 1});
    const Ray r = ray({0, 0, 0}, {1, 0, 0});
    auto t = scene.castRay(r, 100.0);
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 3.0, 1e-12);
    EXPECT_FALSE(scene.castRay(r, 2.5));
    EXPECT_FALSE(scene.castRay(ray({0, 0, 0}, {-1, 0, 0}), 100.0));
}

TEST(Primitives, BoundingBoxesContainTheSolids) {
    Box box;
    box.half_extents = {1, 0.5, 0.25};
    box.T_world_box = Eigen::Translation3d(1, 2, 3) * Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ());
    const Aabb a = boundingBox(box);
    EXPECT_NEAR(a.min.x(), 0.5, 1e-12);
    EXPECT_NEAR(a.max.y(), 3.0, 1e-12);
    const Aabb c = boundingBox(Cylinder{{1, 1}, 0.5, 0, 2});
    EXPECT_NEAR(c.min.x(), 0.5, 1e-12);
    EXPECT_NEAR(c.max.z(), 2.0, 1e-12);
}

}  // namespace
}  // namespace stairmap::sim
