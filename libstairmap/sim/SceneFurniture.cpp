#include "sim/SceneFurniture.h"

#include <algorithm>
#include <cmath>

namespace stairmap::sim {

using V3 = Eigen::Vector3d;

Eigen::Isometry3d groundFrame(const V3& origin, double heading_deg) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(heading_deg * M_PI / 180.0, V3::UnitZ()).toRotationMatrix();
    T.translation() = origin;
    return T;
}

void addLocalBox(Scene& scene, const Eigen::Isometry3d& T, const V3& min, const V3& max) {
    Box box = makeAxisAlignedBox(min, max);
    box.T_world_box = T * box.T_world_box;
    scene.add(box);
}

void addBar(Scene& scene, const Eigen::Isometry3d& T, const V3& a, const V3& b, double size_y,
            double size_z) {
    const V3 x = (b - a).normalized();
    const V3 z = x.cross(V3::UnitY()).normalized();  // up-ish, perpendicular to x
    const V3 y = z.cross(x);
    Box box;
    box.half_extents = {0.5 * (b - a).norm(), 0.5 * size_y, 0.5 * size_z};
    Eigen::Isometry3d T_local = Eigen::Isometry3d::Identity();
    T_local.linear().col(0) = x;
    T_local.linear().col(1) = y;
    T_local.linear().col(2) = z;
    T_local.translation() = 0.5 * (a + b);
    box.T_world_box = T * T_local;
    scene.add(box);
}

void addRailing(Scene& scene, const Eigen::Isometry3d& T, const V3& a, const V3& b, double height_m,
                double post_spacing_m) {
    const double length = (b - a).head<2>().norm();
    const int posts = std::max(2, static_cast<int>(std::ceil(length / post_spacing_m)) + 1);
    for (int i = 0; i < posts; ++i) {
        const V3 p = a + (b - a) * (static_cast<double>(i) / (posts - 1));
        addLocalBox(scene, T, p + V3(-0.02, -0.02, 0.0), p + V3(0.02, 0.02, height_m));
    }
    addBar(scene, T, a + V3(0, 0, height_m), b + V3(0, 0, height_m), 0.05, 0.05);
}

void addBaluster(Scene& scene, const Eigen::Isometry3d& T, const V3& foot, double height_m) {
    const V3 p = T * foot;
    scene.add(Cylinder{p.head<2>(), 0.012, p.z(), p.z() + height_m});
}

void addBench(Scene& scene, const Eigen::Isometry3d& T, double length, double depth,
              double seat_height) {
    const double hl = 0.5 * length, hd = 0.5 * depth;
    addLocalBox(scene, T, {-hl, -hd, seat_height - 0.04}, {hl, hd, seat_height});
    for (double x : {-hl + 0.05, hl - 0.09})
        addLocalBox(scene, T, {x, -hd + 0.03, 0.0}, {x + 0.04, hd - 0.03, seat_height - 0.04});
}

void addTable(Scene& scene, const Eigen::Isometry3d& T, double length, double depth, double height) {
    const double hl = 0.5 * length, hd = 0.5 * depth;
    addLocalBox(scene, T, {-hl, -hd, height - 0.04}, {hl, hd, height});
    for (double x : {-hl + 0.05, hl - 0.1})
        for (double y : {-hd + 0.05, hd - 0.1})
            addLocalBox(scene, T, {x, y, 0.0}, {x + 0.05, y + 0.05, height - 0.04});
}

void addShelf(Scene& scene, const Eigen::Isometry3d& T, double length, double depth, int boards) {
    const double hl = 0.5 * length;
    const double top = 0.1 + 0.38 * boards;
    for (double x : {-hl, hl - 0.02}) addLocalBox(scene, T, {x, 0.0, 0.0}, {x + 0.02, depth, top});
    for (int k = 0; k < boards; ++k) {
        const double z = 0.1 + 0.38 * k;
        addLocalBox(scene, T, {-hl, 0.0, z}, {hl, depth, z + 0.02});
    }
}

}  // namespace stairmap::sim
