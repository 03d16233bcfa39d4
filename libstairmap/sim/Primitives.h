#pragma once
// Solid primitives the simulator's scenes are built from, with analytic ray intersection.
// All quantities in metres and radians, in the world frame (z up).

#include <Eigen/Geometry>
#include <optional>
#include <variant>

namespace stairmap::sim {

/// A half-line origin + t * direction, t >= 0. `direction` must be a unit vector.
struct Ray {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
};

/// Axis-aligned bounding box used for culling.
struct Aabb {
    Eigen::Vector3d min = Eigen::Vector3d::Zero();
    Eigen::Vector3d max = Eigen::Vector3d::Zero();
    /// True if the ray enters the box before t_max (slab test, inclusive).
    bool hitBefore(const Ray& ray, const Eigen::Vector3d& inv_direction, double t_max) const;
};

/// Oriented box: T_world_box places the box centre; half_extents along the box axes [m].
/// A slab (floor, tread, wall) is a thin box.
struct Box {
    Eigen::Isometry3d T_world_box = Eigen::Isometry3d::Identity();
    Eigen::Vector3d half_extents = Eigen::Vector3d::Constant(0.5);
};

/// Vertical solid cylinder (axis along z) with flat caps.
struct Cylinder {
    Eigen::Vector2d centre_xy = Eigen::Vector2d::Zero();
    double radius = 0.5;
    double z_min = 0.0;
    double z_max = 1.0;
};

/// Annular-sector prism around a vertical axis: one step of a spiral staircase.
/// Occupies inner_radius <= r <= outer_radius, angle in [angle_start, angle_start + angle_span]
/// (counter-clockwise from +x, span in (0, 2*pi)), z in [z_min, z_max].
struct HelicalWedge {
    Eigen::Vector2d centre_xy = Eigen::Vector2d::Zero();
    double inner_radius = 0.1;
    double outer_radius = 1.0;
    double angle_start = 0.0;  ///< [rad]
    double angle_span = 0.5;   ///< [rad]
    double z_min = 0.0;
    double z_max = 0.2;
};

using Primitive = std::variant<Box, Cylinder, HelicalWedge>;

/// Axis-aligned box spanning min..max (convenience for floors, walls, treads).
Box makeAxisAlignedBox(const Eigen::Vector3d& min, const Eigen::Vector3d& max);

/// Distance t > 0 along the ray to the first surface hit, or nullopt. A ray starting inside a
/// solid reports the exit point.
std::optional<double> intersect(const Box& box, const Ray& ray);
std::optional<double> intersect(const Cylinder& cylinder, const Ray& ray);
std::optional<double> intersect(const HelicalWedge& wedge, const Ray& ray);
std::optional<double> intersect(const Primitive& primitive, const Ray& ray);

/// World-frame bounding box of a primitive.
Aabb boundingBox(const Primitive& primitive);

}  // namespace stairmap::sim
