#include "sim/NegativeGenerators.h"

#include <cmath>
#include <stdexcept>

#include "sim/StairGenerators.h"

namespace stairmap::sim {

namespace {
constexpr double kDeg = M_PI / 180.0;
using V3 = Eigen::Vector3d;

/// Adds a box given in the feature frame (origin at the foot, x towards the rise).
void addLocalBox(Scene& scene, const Eigen::Isometry3d& T, const V3& min, const V3& max) {
    Box box = makeAxisAlignedBox(min, max);
    box.T_world_box = T * box.T_world_box;
    scene.add(box);
}

void addRoom(Scene& scene, const Eigen::Isometry3d& T) {
    const double h = 2.6;
    addLocalBox(scene, T, {-4.0, -3.2, 0}, {4.0, -3.0, h});  // walls
    addLocalBox(scene, T, {-4.0, 3.0, 0}, {4.0, 3.2, h});
    addLocalBox(scene, T, {-4.2, -3.2, 0}, {-4.0, 3.2, h});
    addLocalBox(scene, T, {4.0, -3.2, 0}, {4.2, 3.2, h});
    // Table with four legs.
    addLocalBox(scene, T, {0.5, -0.5, 0.72}, {1.7, 0.3, 0.76});
    for (double x : {0.55, 1.6})
        for (double y : {-0.45, 0.2}) addLocalBox(scene, T, {x, y, 0}, {x + 0.05, y + 0.05, 0.72});
    // Shelf against the +x wall: side panels and five boards 0.4 m apart.
    for (double y : {-1.5, -0.3}) addLocalBox(scene, T, {3.6, y, 0}, {4.0, y + 0.02, 2.0});
    for (int k = 0; k < 5; ++k) {
        const double z = 0.1 + 0.4 * k;
        addLocalBox(scene, T, {3.6, -1.5, z}, {4.0, -0.28, z + 0.02});
    }
    // Sofa: seat and back; chair; low cabinet.
    addLocalBox(scene, T, {-3.0, 1.8, 0}, {-1.0, 2.7, 0.45});
    addLocalBox(scene, T, {-3.0, 2.7, 0}, {-1.0, 3.0, 0.85});
    addLocalBox(scene, T, {1.9, -1.2, 0}, {2.35, -0.75, 0.46});
    addLocalBox(scene, T, {2.3, -1.2, 0.46}, {2.35, -0.75, 0.9});
    addLocalBox(scene, T, {-3.9, -2.9, 0}, {-2.3, -2.4, 0.9});
}

void addRamp(Scene& scene, const Eigen::Isometry3d& T, const NegativeParams& p) {
    const double slope = p.ramp_slope_deg * kDeg;
    const double length = p.ramp_length_m / std::cos(slope);
    const double thickness = 0.3;
    Box ramp;
    ramp.half_extents = {0.5 * length, 0.5 * p.width_m, 0.5 * thickness};
    // Top surface runs from the foot (0,0,0) up along x; the box hangs below it.
    const Eigen::Matrix3d R = Eigen::AngleAxisd(-slope, V3::UnitY()).toRotationMatrix();
    ramp.T_world_box = Eigen::Isometry3d::Identity();
    ramp.T_world_box.linear() = R;
    ramp.T_world_box.translation() = R * V3(0.5 * length, 0, -0.5 * thickness);
    ramp.T_world_box = T * ramp.T_world_box;
    scene.add(ramp);
    const double top = p.ramp_length_m * std::tan(slope);
    addLocalBox(scene, T, {p.ramp_length_m, -0.5 * p.width_m, 0}, {p.ramp_length_m + 3.0, 0.5 * p.width_m, top});
}

void addTiers(Scene& scene, const Eigen::Isometry3d& T, int tiers, double rise, double run,
              double width, double last_depth) {
    for (int i = 1; i <= tiers; ++i) {
        const double depth = i < tiers ? run : last_depth;
        addLocalBox(scene, T, {(i - 1) * run, -0.5 * width, 0}, {(i - 1) * run + depth, 0.5 * width, i * rise});
    }
}
}  // namespace

void validate(const NegativeParams& p) {
    auto require = [](bool ok, const char* field, const char* what) {
        if (!ok) throw std::invalid_argument(std::string(field) + ": " + what);
    };
    require(p.width_m > 0.2 && p.width_m < 30, "width_m", "must be in (0.2, 30) m");
    require(p.ramp_slope_deg > 0 && p.ramp_slope_deg < 45, "ramp_slope_deg", "must be in (0, 45) deg");
    require(p.ramp_length_m > 0.2 && p.ramp_length_m < 30, "ramp_length_m", "must be in (0.2, 30) m");
    require(p.curb_height_m > 0 && p.curb_height_m < 1, "curb_height_m", "must be in (0, 1) m");
    require(p.stage_steps >= 1 && p.stage_steps <= 2, "stage_steps", "must be 1 or 2");
    require(p.stage_rise_m > 0 && p.stage_rise_m < 1, "stage_rise_m", "must be in (0, 1) m");
    require(p.stage_run_m > 0.05 && p.stage_run_m < 2, "stage_run_m", "must be in (0.05, 2) m");
    require(p.bleacher_tiers >= 2 && p.bleacher_tiers <= 20, "bleacher_tiers", "must be 2..20");
    require(p.bleacher_rise_m >= 0.35 && p.bleacher_rise_m < 2, "bleacher_rise_m", "must be 0.35..2 m (lower tiers are steps)");
    require(p.bleacher_run_m > 0.2 && p.bleacher_run_m < 3, "bleacher_run_m", "must be in (0.2, 3) m");
    require(p.origin.allFinite(), "origin", "must be finite");
}

void addNegative(Scene& scene, const NegativeParams& p) {
    validate(p);
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(p.heading_deg * kDeg, V3::UnitZ()).toRotationMatrix();
    T.translation() = p.origin;
    if (p.type == "room") {
        addRoom(scene, T);
    } else if (p.type == "ramp") {
        addRamp(scene, T, p);
    } else if (p.type == "curb") {
        addLocalBox(scene, T, {0, -0.5 * p.width_m, 0}, {6.0, 0.5 * p.width_m, p.curb_height_m});
    } else if (p.type == "stage") {
        addTiers(scene, T, p.stage_steps + 1, p.stage_rise_m, p.stage_run_m, p.width_m, 4.0);
    } else if (p.type == "bleachers") {
        addTiers(scene, T, p.bleacher_tiers, p.bleacher_rise_m, p.bleacher_run_m, p.width_m,
                 p.bleacher_run_m);
    } else {
        throw std::invalid_argument("type: '" + p.type +
                                    "' is not a negative scene (room, ramp, curb, stage, bleachers)");
    }
    const Eigen::Vector2d o = p.origin.head<2>();
    addFloor(scene, o - Eigen::Vector2d(15, 15), o + Eigen::Vector2d(15, 15), p.origin.z());
    scene.truth().floor_heights = {p.origin.z()};
}

}  // namespace stairmap::sim
