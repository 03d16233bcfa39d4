#include "sim/Primitives.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace stairmap::sim {

namespace {
constexpr double kMinT = 1e-9;   // ignore hits at the ray origin itself
constexpr double kTol = 1e-9;    // inclusion tolerance for surface points [m]

/// Keeps the smallest positive candidate.
void keepNearest(double t, std::optional<double>& best) {
    if (t > kMinT && (!best || t < *best)) best = t;
}

double wrapAngle(double a) {
    a = std::fmod(a, 2.0 * M_PI);
    return a < 0 ? a + 2.0 * M_PI : a;
}

bool insideWedge(const HelicalWedge& w, const Eigen::Vector3d& p, double tol) {
    if (p.z() < w.z_min - tol || p.z() > w.z_max + tol) return false;
    const Eigen::Vector2d d = p.head<2>() - w.centre_xy;
    const double r = d.norm();
    if (r < w.inner_radius - tol || r > w.outer_radius + tol) return false;
    const double rel = wrapAngle(std::atan2(d.y(), d.x()) - w.angle_start);
    const double ang_tol = r > 1e-6 ? tol / r : M_PI;
    return rel <= w.angle_span + ang_tol || rel >= 2.0 * M_PI - ang_tol;
}

/// Roots of |(o + t d).xy - c| = radius.
void cylinderRoots(const Eigen::Vector2d& c, double radius, const Ray& ray,
                   std::array<double, 2>& roots, int& count) {
    count = 0;
    const Eigen::Vector2d o = ray.origin.head<2>() - c;
    const Eigen::Vector2d d = ray.direction.head<2>();
    const double a = d.squaredNorm();
    if (a < 1e-18) return;
    const double b = 2.0 * o.dot(d);
    const double cc = o.squaredNorm() - radius * radius;
    const double disc = b * b - 4.0 * a * cc;
    if (disc < 0) return;
    const double s = std::sqrt(disc);
    roots[0] = (-b - s) / (2.0 * a);
    roots[1] = (-b + s) / (2.0 * a);
    count = 2;
}
}  // namespace

bool Aabb::hitBefore(const Ray& ray, const Eigen::Vector3d& inv_direction, double t_max) const {
    double t_enter = 0.0;
    double t_exit = t_max;
    for (int i = 0; i < 3; ++i) {
        double t0 = (min[i] - ray.origin[i]) * inv_direction[i];
        double t1 = (max[i] - ray.origin[i]) * inv_direction[i];
        if (std::isnan(t0) || std::isnan(t1)) continue;  // parallel ray exactly on a face
        if (t0 > t1) std::swap(t0, t1);
        t_enter = std::max(t_enter, t0);
        t_exit = std::min(t_exit, t1);
        if (t_enter > t_exit) return false;
    }
    return true;
}

Box makeAxisAlignedBox(const Eigen::Vector3d& min, const Eigen::Vector3d& max) {
    Box box;
    box.T_world_box = Eigen::Isometry3d::Identity();
    box.T_world_box.translation() = 0.5 * (min + max);
    box.half_extents = 0.5 * (max - min).cwiseAbs();
    return box;
}

std::optional<double> intersect(const Box& box, const Ray& ray) {
    const Eigen::Isometry3d T_box_world = box.T_world_box.inverse();
    const Eigen::Vector3d o = T_box_world * ray.origin;
    const Eigen::Vector3d d = T_box_world.linear() * ray.direction;
    double t_enter = -std::numeric_limits<double>::infinity();
    double t_exit = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        const double h = box.half_extents[i];
        if (std::abs(d[i]) < 1e-15) {
            if (o[i] < -h || o[i] > h) return std::nullopt;
            continue;
        }
        double t0 = (-h - o[i]) / d[i];
        double t1 = (h - o[i]) / d[i];
        if (t0 > t1) std::swap(t0, t1);
        t_enter = std::max(t_enter, t0);
        t_exit = std::min(t_exit, t1);
    }
    if (t_enter > t_exit || t_exit <= kMinT) return std::nullopt;
    return t_enter > kMinT ? t_enter : t_exit;
}

std::optional<double> intersect(const Cylinder& cyl, const Ray& ray) {
    std::optional<double> best;
    std::array<double, 2> roots{};
    int count = 0;
    cylinderRoots(cyl.centre_xy, cyl.radius, ray, roots, count);
    for (int i = 0; i < count; ++i) {
        const double z = ray.origin.z() + roots[i] * ray.direction.z();
        if (z >= cyl.z_min - kTol && z <= cyl.z_max + kTol) keepNearest(roots[i], best);
    }
    if (std::abs(ray.direction.z()) > 1e-15) {
        for (double zc : {cyl.z_min, cyl.z_max}) {
            const double t = (zc - ray.origin.z()) / ray.direction.z();
            const Eigen::Vector2d p = (ray.origin + t * ray.direction).head<2>();
            if ((p - cyl.centre_xy).norm() <= cyl.radius + kTol) keepNearest(t, best);
        }
    }
    return best;
}

std::optional<double> intersect(const HelicalWedge& w, const Ray& ray) {
    // Candidate hits on every bounding surface; a candidate counts if it lies on the solid.
    std::optional<double> best;
    auto consider = [&](double t) {
        if (t > kMinT && (!best || t < *best) && insideWedge(w, ray.origin + t * ray.direction, 1e-7))
            best = t;
    };
    std::array<double, 2> roots{};
    int count = 0;
    for (double radius : {w.inner_radius, w.outer_radius}) {
        cylinderRoots(w.centre_xy, radius, ray, roots, count);
        for (int i = 0; i < count; ++i) consider(roots[i]);
    }
    if (std::abs(ray.direction.z()) > 1e-15) {
        for (double zc : {w.z_min, w.z_max}) consider((zc - ray.origin.z()) / ray.direction.z());
    }
    for (double a : {w.angle_start, w.angle_start + w.angle_span}) {
        const Eigen::Vector2d n(-std::sin(a), std::cos(a));  // normal of the radial plane
        const double denom = n.dot(ray.direction.head<2>());
        if (std::abs(denom) < 1e-15) continue;
        consider(-n.dot(ray.origin.head<2>() - w.centre_xy) / denom);
    }
    return best;
}

std::optional<double> intersect(const Primitive& primitive, const Ray& ray) {
    return std::visit([&](const auto& p) { return intersect(p, ray); }, primitive);
}

Aabb boundingBox(const Primitive& primitive) {
    Aabb box;
    if (const auto* b = std::get_if<Box>(&primitive)) {
        const Eigen::Vector3d extent = b->T_world_box.linear().cwiseAbs() * b->half_extents;
        box.min = b->T_world_box.translation() - extent;
        box.max = b->T_world_box.translation() + extent;
    } else if (const auto* c = std::get_if<Cylinder>(&primitive)) {
        box.min << c->centre_xy - Eigen::Vector2d::Constant(c->radius), c->z_min;
        box.max << c->centre_xy + Eigen::Vector2d::Constant(c->radius), c->z_max;
    } else {
        const auto& w = std::get<HelicalWedge>(primitive);
        box.min << w.centre_xy - Eigen::Vector2d::Constant(w.outer_radius), w.z_min;
        box.max << w.centre_xy + Eigen::Vector2d::Constant(w.outer_radius), w.z_max;
    }
    return box;
}

}  // namespace stairmap::sim
