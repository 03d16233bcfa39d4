// Negative features of random scenes (no staircase): furnished rooms, ramps up and down, curbs,
// 1-2 step stages, bleachers, benches/tables/shelves. See RandomSceneBuild.h.

#include <cmath>

#include "sim/NegativeGenerators.h"
#include "sim/RandomDraw.h"
#include "sim/RandomSceneBuild.h"
#include "sim/SceneFurniture.h"
#include "sim/StairGenerators.h"

namespace stairmap::sim {

namespace {
using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;
constexpr double kDeg = M_PI / 180.0;

V3 atBearing(double distance, double bearing_deg, double z = 0.0) {
    return {distance * std::cos(bearing_deg * kDeg), distance * std::sin(bearing_deg * kDeg), z};
}

/// One bench, table or shelf at `centre` (frame on the floor), never closer than 0.4 m to the robot.
void addFurniturePiece(Scene& scene, RandomDraw& d, const Eigen::Isometry3d& T) {
    const double len = d.uniform(0.8, 2.0), depth = d.uniform(0.3, 0.9);
    const double reach = 0.5 * std::hypot(len, depth) + 0.4;
    if (T.translation().head<2>().norm() < reach) return;
    switch (d.integer(0, 2)) {
        case 0: addBench(scene, T, len, std::min(depth, 0.45), d.uniform(0.40, 0.48)); break;
        case 1: addTable(scene, T, len, std::max(depth, 0.6), d.uniform(0.70, 0.78)); break;
        default: addShelf(scene, T, len, std::min(depth, 0.45), d.integer(3, 5)); break;
    }
}

/// Room 8 x 6.4 m (sim/NegativeGenerators' "room": table, shelf, sofa, chair, cabinet) with the
/// robot in its clear middle strip, plus `pieces` more pieces of furniture.
void addFurnishedRoom(Scene& scene, const NegativeSpec& n, RandomDraw& d) {
    const V3 robot_local(d.uniform(-0.8, 0.2), d.uniform(-2.0, 1.4), 0.0);
    NegativeParams p;
    p.type = "room";
    p.heading_deg = n.heading_deg;
    p.origin = -(groundFrame(V3::Zero(), n.heading_deg).linear() * robot_local);
    addNegative(scene, p);
    const Eigen::Isometry3d T_room = groundFrame(p.origin, n.heading_deg);
    for (int i = 0; i < n.tiers; ++i) {
        const V3 local(d.uniform(-3.0, 3.0), d.uniform(-2.4, 2.4), 0.0);
        addFurniturePiece(scene, d, T_room * groundFrame(local, d.uniform(0.0, 360.0)));
    }
}

/// Ramp down: the robot stands on the top floor (z = 0), the ramp falls away from it.
void addRampDown(Scene& scene, const NegativeSpec& n) {
    const double drop = n.run_m * std::tan(n.slope_deg * kDeg);
    const V3 edge = atBearing(n.distance_m, n.bearing_deg);
    NegativeParams p;
    p.type = "ramp";
    p.heading_deg = n.heading_deg;  // up the ramp, towards the robot
    p.width_m = n.width_m;
    p.ramp_slope_deg = n.slope_deg;
    p.ramp_length_m = n.run_m;
    const Eigen::Isometry3d R = groundFrame(V3::Zero(), n.heading_deg);
    p.origin = edge - R.linear() * V3(n.run_m, 0.0, 0.0) - V3(0, 0, drop);
    addNegative(scene, p);
    const Eigen::Isometry3d T = groundFrame(p.origin, n.heading_deg);
    const V3 r = T.inverse() * V3::Zero();
    addLocalBox(scene, T, {n.run_m, r.y() - 4.0, 0.0}, {r.x() + 4.0, r.y() + 4.0, drop});
}
}  // namespace

void addRandomExtra(Scene& scene, const NegativeSpec& n, std::uint64_t seed, int index) {
    RandomDraw d(seed, static_cast<std::uint64_t>(index), 0xe8a5ULL);
    if (n.type == "room") return addFurnishedRoom(scene, n, d);
    if (n.type == "ramp_down") return addRampDown(scene, n);
    if (n.type == "furniture") {
        addFloor(scene, {-15, -15}, {15, 15}, 0.0);
        for (int i = 0; i < n.tiers; ++i) {
            const V3 c = atBearing(d.uniform(1.0, 4.0), n.bearing_deg + d.uniform(-60.0, 60.0));
            addFurniturePiece(scene, d, groundFrame(c, d.uniform(0.0, 360.0)));
        }
        return;
    }
    NegativeParams p;
    p.origin = atBearing(n.distance_m, n.bearing_deg);
    p.heading_deg = n.heading_deg;
    p.width_m = n.width_m;
    if (n.type == "ramp_up") {
        p.type = "ramp";
        p.ramp_slope_deg = n.slope_deg;
        p.ramp_length_m = n.run_m;
    } else if (n.type == "curb") {
        p.type = "curb";
        p.curb_height_m = n.height_m;
    } else if (n.type == "stage") {
        p.type = "stage";
        p.stage_steps = n.tiers;
        p.stage_rise_m = n.height_m;
        p.stage_run_m = n.run_m;
    } else {
        p.type = "bleachers";
        p.bleacher_tiers = n.tiers;
        p.bleacher_rise_m = n.height_m;
        p.bleacher_run_m = n.run_m;
    }
    addNegative(scene, p);
}

}  // namespace stairmap::sim
