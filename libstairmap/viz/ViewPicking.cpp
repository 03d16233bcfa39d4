#include "viz/ViewPicking.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace stairmap::viz {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

/// Ray parameter t of the closest approach to segment [a, b], if within `tolerance` [m].
std::optional<double> hitSegment(const ViewRay& ray, const Eigen::Vector3d& a,
                                 const Eigen::Vector3d& b, double tolerance) {
    const Eigen::Vector3d u = ray.direction, v = b - a, w = ray.origin - a;
    const double uv = u.dot(v), vv = v.squaredNorm(), uw = u.dot(w), vw = v.dot(w);
    const double denom = vv - uv * uv;  // |u| = 1
    double s = denom > 1e-12 ? (vw - uv * uw) / denom : 0.0;  // along the segment, 0..1
    s = std::clamp(s, 0.0, 1.0);
    const double t = std::max(0.0, (a + s * v - ray.origin).dot(u));
    if ((ray.origin + t * u - (a + s * v)).norm() > tolerance) return std::nullopt;
    return t;
}

/// Ray parameter where the ray crosses the tread drawn behind a step edge (the horizontal quad
/// start, end, end + behind, start + behind at the edge's height), if it does.
std::optional<double> hitTread(const ViewRay& ray, const StairEdge& edge,
                               const Eigen::Vector2d& behind) {
    if (std::abs(ray.direction.z()) < 1e-9) return std::nullopt;
    const double t = (edge.centre().z() - ray.origin.z()) / ray.direction.z();
    if (t <= 0.0) return std::nullopt;
    const Eigen::Vector2d p = (ray.origin + t * ray.direction).head<2>();
    const Eigen::Vector2d a = edge.start.head<2>(), b = edge.end.head<2>();
    const Eigen::Vector2d quad[4] = {a, b, b + behind, a + behind};
    int sign = 0;  // inside a convex quad: the same side of all four edges
    for (int i = 0; i < 4; ++i) {
        const Eigen::Vector2d e = quad[(i + 1) % 4] - quad[i], r = p - quad[i];
        const double cross = e.x() * r.y() - e.y() * r.x();
        const int s = cross > 0 ? 1 : (cross < 0 ? -1 : 0);
        if (s == 0) continue;
        if (sign != 0 && s != sign) return std::nullopt;
        sign = s;
    }
    return t;
}

/// Nearest hit of one landmark along the ray: its step edges and the treads the viewer draws
/// (one run deep behind each nosing, uphill; see landmarkObjects), the last one included.
std::optional<double> hitLandmark(const Staircase& stairs, const ViewRay& ray,
                                  const PickParams& params) {
    std::optional<double> best;
    const auto keep = [&best](std::optional<double> t) {
        if (t && (!best || *t < *best)) best = t;
    };
    const double depth = stairs.step_depth > 0 ? stairs.step_depth : kDrawnTreadDepthM;
    const double uphill = stairs.heading_rad +
                          (stairs.direction == StairDirection::Ascending ? 0.0 : M_PI);
    const Eigen::Vector2d behind = depth * Eigen::Vector2d(std::cos(uphill), std::sin(uphill));
    for (const StairEdge& edge : stairs.steps) {
        keep(hitSegment(ray, edge.start, edge.end, params.edge_tolerance_m));
        keep(hitTread(ray, edge, behind));
    }
    return best;
}

}  // namespace

Eigen::Vector3d eyePosition(const CameraView& view) {
    const double az = view.azimuth_deg * kDegToRad, el = view.elevation_deg * kDegToRad;
    return view.target + view.distance_m * Eigen::Vector3d(std::cos(el) * std::cos(az),
                                                          std::cos(el) * std::sin(az),
                                                          std::sin(el));
}

ViewRay rayThroughPixel(const CameraView& view, const ViewImage& image, double x_px, double y_px) {
    ViewRay ray;
    ray.origin = eyePosition(view);
    const Eigen::Vector3d forward = (view.target - ray.origin).normalized();
    // z is up unless the camera looks straight down or up, where the azimuth fixes "up" (as MRPT's
    // camera does near +-90 deg elevation).
    Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ());
    if (right.norm() < 1e-6) {
        const double az = view.azimuth_deg * kDegToRad;
        right = Eigen::Vector3d(std::sin(az), -std::cos(az), 0.0);
    }
    right.normalize();
    const Eigen::Vector3d up = right.cross(forward);
    const double tan_half = std::tan(0.5 * image.vertical_fov_deg * kDegToRad);
    const double aspect = double(image.width_px) / image.height_px;
    const double ndc_x = 2.0 * x_px / image.width_px - 1.0;   // -1 left .. +1 right
    const double ndc_y = 1.0 - 2.0 * y_px / image.height_px;  // +1 top .. -1 bottom
    ray.direction =
        (forward + ndc_x * tan_half * aspect * right + ndc_y * tan_half * up).normalized();
    return ray;
}

int pickLandmark(const std::vector<StaircaseLandmark>& landmarks, const ViewRay& ray,
                 const PickParams& params) {
    int picked = -1;
    double nearest = std::numeric_limits<double>::infinity();
    for (const StaircaseLandmark& l : landmarks) {
        const std::optional<double> t = hitLandmark(l.stairs, ray, params);
        if (t && *t < nearest) {
            nearest = *t;
            picked = l.id;
        }
    }
    return picked;
}

}  // namespace stairmap::viz
