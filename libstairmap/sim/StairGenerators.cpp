#include "sim/StairGenerators.h"

#include <cmath>
#include <random>
#include <stdexcept>

namespace stairmap::sim {

namespace {
constexpr double kDeg = M_PI / 180.0;
constexpr double kWallThickness = 0.1;  // [m]

void require(bool ok, const std::string& field, const char* what) {
    if (!ok) throw std::invalid_argument(field + ": " + what);
}

/// Box given in the stair frame (axis aligned there), placed in the world.
Box stairBox(const Eigen::Isometry3d& T_world_stair, const Eigen::Vector3d& min,
             const Eigen::Vector3d& max) {
    Box box = makeAxisAlignedBox(min, max);
    box.T_world_box = T_world_stair * box.T_world_box;
    return box;
}

void addDebris(Scene& scene, const Eigen::Isometry3d& T_world_stair, const StraightStairParams& p) {
    std::mt19937 rng(p.debris_seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < p.debris_count; ++k) {
        const int tread = 1 + static_cast<int>(unit(rng) * (p.num_risers - 1));  // 1..N-1
        const double sx = 0.04 + unit(rng) * (std::min(p.debris_max_size_m, p.run_m) - 0.04);
        const double sy = 0.04 + unit(rng) * (p.debris_max_size_m - 0.04);
        const double sz = 0.03 + unit(rng) * 0.6 * (std::min(p.debris_max_size_m, p.rise_m) - 0.03);
        const double x = (tread - 1) * p.run_m + unit(rng) * (p.run_m - sx);
        const double y = (unit(rng) - 0.5) * (p.width_m - sy);
        const double z = tread * p.rise_m;
        Box box = makeAxisAlignedBox({x, y - 0.5 * sy, z}, {x + sx, y + 0.5 * sy, z + sz});
        const Eigen::Vector3d c = box.T_world_box.translation();
        box.T_world_box = T_world_stair * Eigen::Translation3d(c) *
                          Eigen::AngleAxisd((unit(rng) - 0.5) * 0.6, Eigen::Vector3d::UnitZ());
        scene.add(box);
    }
}

void addStraightSolids(Scene& scene, const Eigen::Isometry3d& T, const StraightStairParams& p) {
    const double hw = 0.5 * p.width_m;
    const int n = p.num_risers;
    for (int i = 1; i < n; ++i) {  // treads 1..N-1; tread N is the landing
        const double x0 = (i - 1) * p.run_m;
        const double z_top = i * p.rise_m;
        const double z_bottom = p.open_risers ? z_top - p.tread_thickness_m : 0.0;
        scene.add(stairBox(T, {x0, -hw, z_bottom}, {x0 + p.run_m, hw, z_top}));
    }
    const double land_hw = 0.5 * (p.landing_width_m > 0 ? p.landing_width_m : p.width_m);
    const double lx0 = (n - 1) * p.run_m;
    const double top = n * p.rise_m;
    const double land_bottom = p.solid_landing ? 0.0 : top - p.landing_thickness_m;
    scene.add(stairBox(T, {lx0, -land_hw, land_bottom}, {lx0 + p.landing_depth_m, land_hw, top}));
    const double wall_top = top + p.wall_height_m;
    const double wall_x1 = lx0 + p.landing_depth_m;
    if (p.wall_left) {
        scene.add(stairBox(T, {-0.3, hw, 0.0}, {wall_x1, hw + kWallThickness, wall_top}));
    }
    if (p.wall_right) {
        scene.add(stairBox(T, {-0.3, -hw - kWallThickness, 0.0}, {wall_x1, -hw, wall_top}));
    }
}
}  // namespace

void validate(const StraightStairParams& p) {
    require(p.num_risers >= 1 && p.num_risers <= 100, p.name + ".num_risers", "must be 1..100");
    require(p.rise_m > 0.01 && p.rise_m < 1.0, p.name + ".rise_m", "must be in (0.01, 1) m");
    require(p.run_m > 0.05 && p.run_m < 2.0, p.name + ".run_m", "must be in (0.05, 2) m");
    require(p.width_m > 0.1 && p.width_m < 20.0, p.name + ".width_m", "must be in (0.1, 20) m");
    require(p.tread_thickness_m > 0 && p.tread_thickness_m <= p.rise_m,
            p.name + ".tread_thickness_m", "must be in (0, rise_m]");
    require(p.landing_depth_m > 0, p.name + ".landing_depth_m", "must be > 0");
    require(p.landing_thickness_m > 0, p.name + ".landing_thickness_m", "must be > 0");
    require(p.debris_count >= 0 && p.debris_count <= 1000, p.name + ".debris_count",
            "must be 0..1000");
    require(p.debris_max_size_m > 0.04, p.name + ".debris_max_size_m", "must be > 0.04 m");
    require(p.origin.allFinite(), p.name + ".origin", "must be finite");
}

std::size_t addStraightStair(Scene& scene, const StraightStairParams& p) {
    validate(p);
    Eigen::Isometry3d T_world_stair = Eigen::Isometry3d::Identity();
    T_world_stair.linear() =
        Eigen::AngleAxisd(p.heading_deg * kDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T_world_stair.translation() = p.origin;
    addStraightSolids(scene, T_world_stair, p);
    if (p.debris_count > 0) addDebris(scene, T_world_stair, p);

    StaircaseTruth truth;
    truth.name = p.name;
    truth.kind = p.kind;
    truth.rise_m = p.rise_m;
    truth.run_m = p.run_m;
    truth.width_m = p.width_m;
    truth.num_risers = p.num_risers;
    truth.bottom_z = p.origin.z();
    truth.top_z = p.origin.z() + p.num_risers * p.rise_m;
    for (int i = 1; i <= p.num_risers; ++i) {
        const double x = (i - 1) * p.run_m;
        const double z = i * p.rise_m;
        truth.nosings.push_back({T_world_stair * Eigen::Vector3d(x, -0.5 * p.width_m, z),
                                 T_world_stair * Eigen::Vector3d(x, 0.5 * p.width_m, z)});
    }
    scene.truth().staircases.push_back(truth);
    return scene.truth().staircases.size() - 1;
}

void validate(const SpiralStairParams& p) {
    require(p.num_risers >= 2 && p.num_risers <= 100, p.name + ".num_risers", "must be 2..100");
    require(p.rise_m > 0.01 && p.rise_m < 1.0, p.name + ".rise_m", "must be in (0.01, 1) m");
    require(p.column_radius_m > 0 && p.column_radius_m < p.outer_radius_m,
            p.name + ".column_radius_m", "must be in (0, outer_radius_m)");
    require(p.outer_radius_m < 10, p.name + ".outer_radius_m", "must be < 10 m");
    require(p.step_angle_deg > 1 && p.step_angle_deg * (p.num_risers - 1) + p.landing_angle_deg < 360,
            p.name + ".step_angle_deg", "must be > 1 deg and the flight must turn < 360 deg");
    require(p.tread_thickness_m >= 0 && p.tread_thickness_m <= p.rise_m,
            p.name + ".tread_thickness_m", "must be in [0, rise_m]");
    require(p.landing_angle_deg > 1, p.name + ".landing_angle_deg", "must be > 1 deg");
}

std::size_t addSpiralStair(Scene& scene, const SpiralStairParams& p) {
    validate(p);
    const double sign = p.clockwise ? -1.0 : 1.0;
    const double step = p.step_angle_deg * kDeg;
    const double thickness = p.tread_thickness_m > 0 ? p.tread_thickness_m : p.rise_m;
    auto nosingAngle = [&](int i) { return p.start_angle_deg * kDeg + sign * (i - 1) * step; };
    for (int i = 1; i <= p.num_risers; ++i) {
        HelicalWedge w;
        w.centre_xy = p.centre.head<2>();
        w.inner_radius = p.column_radius_m;
        w.outer_radius = p.outer_radius_m;
        w.angle_span = i < p.num_risers ? step : p.landing_angle_deg * kDeg;
        w.angle_start = p.clockwise ? nosingAngle(i) - w.angle_span : nosingAngle(i);
        w.z_max = p.centre.z() + i * p.rise_m;
        w.z_min = w.z_max - thickness;
        scene.add(w);
    }
    const double top_z = p.centre.z() + p.num_risers * p.rise_m;
    if (p.central_column) {
        scene.add(Cylinder{p.centre.head<2>(), p.column_radius_m, p.centre.z(), top_z + 2.0});
    }

    StaircaseTruth truth;
    truth.name = p.name;
    truth.kind = StairKind::Spiral;
    truth.rise_m = p.rise_m;
    const double r_mid = 0.5 * (p.column_radius_m + p.outer_radius_m);
    truth.run_m = 2.0 * r_mid * std::sin(0.5 * step);
    truth.width_m = p.outer_radius_m - p.column_radius_m;
    truth.num_risers = p.num_risers;
    truth.bottom_z = p.centre.z();
    truth.top_z = top_z;
    for (int i = 1; i <= p.num_risers; ++i) {
        const Eigen::Vector3d dir(std::cos(nosingAngle(i)), std::sin(nosingAngle(i)), 0.0);
        const Eigen::Vector3d base = p.centre + Eigen::Vector3d(0, 0, i * p.rise_m);
        truth.nosings.push_back({base + p.column_radius_m * dir, base + p.outer_radius_m * dir});
    }
    scene.truth().staircases.push_back(truth);
    return scene.truth().staircases.size() - 1;
}

void addFloor(Scene& scene, const Eigen::Vector2d& min_xy, const Eigen::Vector2d& max_xy, double z) {
    scene.add(makeAxisAlignedBox({min_xy.x(), min_xy.y(), z - 0.1}, {max_xy.x(), max_xy.y(), z}));
}

}  // namespace stairmap::sim
