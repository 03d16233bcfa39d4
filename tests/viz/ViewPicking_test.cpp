// Clicking a landmark: the pixel ray against MRPT's own rendering of a marker (an independent check
// of the camera model), and picking the first landmark along a ray.
#include <gtest/gtest.h>

#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/COpenGLScene.h>

#include "viz/HeadlessRenderer.h"
#include "viz/ViewPicking.h"

namespace stairmap::viz {
namespace {

double distanceToRay(const ViewRay& ray, const Eigen::Vector3d& p) {
    const Eigen::Vector3d w = p - ray.origin;
    return (w - w.dot(ray.direction) * ray.direction).norm();
}

TEST(ViewPicking, CentrePixelLooksAtTheTarget) {
    CameraView v;
    v.target = {1.0, 2.0, 0.5};
    v.distance_m = 7.0;
    v.azimuth_deg = 120.0;
    v.elevation_deg = 35.0;
    const ViewImage image{640, 360, 60.0};
    const ViewRay ray = rayThroughPixel(v, image, 320.0, 180.0);
    EXPECT_NEAR((ray.origin - v.target).norm(), 7.0, 1e-9);
    EXPECT_LT(distanceToRay(ray, v.target), 1e-9);
    // The top edge of the picture is 30 deg above the line of sight (vertical FOV 60 deg).
    const ViewRay top = rayThroughPixel(v, image, 320.0, 0.0);
    EXPECT_NEAR(std::acos(top.direction.dot(ray.direction)) * 180.0 / M_PI, 30.0, 1e-6);
}

/// Renders one small bright box at `p` and returns the centroid of its pixels.
Eigen::Vector2d renderedCentroid(HeadlessRenderer& renderer, const CameraView& view,
                                 const Eigen::Vector3d& p) {
    mrpt::opengl::COpenGLScene scene;
    scene.getViewport()->setCustomBackgroundColor({0.f, 0.f, 0.f});
    const double h = 0.05;  // [m] half size
    auto box = mrpt::opengl::CBox::Create(mrpt::math::TPoint3D(p.x() - h, p.y() - h, p.z() - h),
                                          mrpt::math::TPoint3D(p.x() + h, p.y() + h, p.z() + h));
    box->setColor_u8(255, 255, 255);
    scene.insert(box);
    mrpt::img::CImage img;
    renderer.render(scene, view, img);
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    int n = 0;
    for (int y = 0; y < renderer.height(); ++y)
        for (int x = 0; x < renderer.width(); ++x)
            if (*img(x, y, 0) > 100) {
                sum += Eigen::Vector2d(x + 0.5, y + 0.5);
                ++n;
            }
    EXPECT_GT(n, 0) << "the marker is not in the picture";
    return n > 0 ? Eigen::Vector2d(sum / n) : Eigen::Vector2d::Zero();
}

TEST(ViewPicking, RayThroughTheRenderedMarkerPassesThroughIt) {
    HeadlessRenderer renderer(480, 270);
    const ViewImage image{480, 270, 60.0};
    struct Case {
        double az, el, dist;
        Eigen::Vector3d target, marker;
    };
    const Case cases[] = {{30.0, 40.0, 8.0, {0, 0, 0}, {1.5, -0.8, 0.6}},
                          {-90.0, 89.5, 12.0, {2, 1, 0}, {-1.0, 3.0, 0.2}},  // the top camera
                          {200.0, 20.0, 6.0, {0, 0, 1}, {-0.5, 1.2, 1.5}}};
    for (const Case& c : cases) {
        CameraView v;
        v.target = c.target;
        v.azimuth_deg = c.az;
        v.elevation_deg = c.el;
        v.distance_m = c.dist;
        const Eigen::Vector2d px = renderedCentroid(renderer, v, c.marker);
        const ViewRay ray = rayThroughPixel(v, image, px.x(), px.y());
        // The ray passes through the 10 cm marker cube, give or take a pixel (~2.4 cm at 8 m):
        // the centroid of its visible faces is not quite its centre. A wrong camera model (axes,
        // aspect, field of view) misses by many pixels.
        const double pixel_m = 2.0 * (ray.origin - c.marker).norm() * std::tan(M_PI / 6) / 270.0;
        EXPECT_LT(distanceToRay(ray, c.marker), 0.05 + pixel_m) << "az " << c.az << " el " << c.el;
    }
}

/// A straight ascending flight of `n` steps along +x from x0, 1 m wide, rise 0.17 m, run 0.28 m.
StaircaseLandmark flight(int id, double x0, int n) {
    StaircaseLandmark l;
    l.id = id;
    for (int i = 0; i < n; ++i) {
        StairEdge e;
        e.start = {x0 + 0.28 * i, 0.5, 0.17 * (i + 1)};
        e.end = {x0 + 0.28 * i, -0.5, 0.17 * (i + 1)};
        l.stairs.steps.push_back(e);
    }
    l.stairs.step_depth = 0.28;
    l.stairs.heading_rad = 0.0;  // uphill along +x
    l.stairs.direction = StairDirection::Ascending;
    return l;
}

ViewRay rayFrom(const Eigen::Vector3d& origin, const Eigen::Vector3d& towards) {
    return {origin, (towards - origin).normalized()};
}

TEST(ViewPicking, PicksTheFirstLandmarkAlongTheRay) {
    const std::vector<StaircaseLandmark> map = {flight(3, 0.0, 5), flight(7, 4.0, 5)};
    // Straight down onto the second tread of each flight.
    EXPECT_EQ(pickLandmark(map, rayFrom({0.42, 0.1, 10.0}, {0.42, 0.1, 0.0})), 3);
    EXPECT_EQ(pickLandmark(map, rayFrom({4.42, 0.1, 10.0}, {4.42, 0.1, 0.0})), 7);
    // Along +x at step height: both flights lie on the ray, the nearer one is picked.
    EXPECT_EQ(pickLandmark(map, rayFrom({-5.0, 0.0, 0.34}, {10.0, 0.0, 0.34})), 3);
    EXPECT_EQ(pickLandmark(map, rayFrom({15.0, 0.0, 0.34}, {-10.0, 0.0, 0.34})), 7);
    // Beside the flights (2 m to the side) and pointing away: nothing.
    EXPECT_EQ(pickLandmark(map, rayFrom({0.42, 2.5, 10.0}, {0.42, 2.5, 0.0})), -1);
    EXPECT_EQ(pickLandmark(map, rayFrom({-5.0, 0.0, 0.34}, {-10.0, 0.0, 0.34})), -1);
    // The top tread as drawn: one run (0.28 m) behind the last nosing at x = 1.12, beyond the
    // edge tolerance; past its far end, nothing.
    EXPECT_EQ(pickLandmark(map, rayFrom({1.35, 0.0, 10.0}, {1.35, 0.0, 0.0})), 3);
    EXPECT_EQ(pickLandmark(map, rayFrom({1.60, 0.0, 10.0}, {1.60, 0.0, 0.0})), -1);
    // Just below the lowest nosing (x = 0, no tread in front of it) but within the edge tolerance.
    EXPECT_EQ(pickLandmark(map, rayFrom({-0.10, 0.0, 10.0}, {-0.10, 0.0, 0.0})), 3);
    EXPECT_EQ(pickLandmark(map, rayFrom({-0.30, 0.0, 10.0}, {-0.30, 0.0, 0.0})), -1);
}

}  // namespace
}  // namespace stairmap::viz
