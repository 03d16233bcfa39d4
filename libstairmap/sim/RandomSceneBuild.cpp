#include "sim/RandomSceneBuild.h"

#include <algorithm>
#include <cmath>

#include "sim/RandomFlightGeometry.h"
#include "sim/SceneFurniture.h"
#include "sim/StairGenerators.h"

namespace stairmap::sim {

namespace {
using V3 = Eigen::Vector3d;
constexpr double kDeg = M_PI / 180.0;
constexpr double kFloorHalf = 15.0;  // [m] floors reach this far from the robot

StairKind kindOf(RandomFamily family) {
    switch (family) {
        case RandomFamily::Hollow: return StairKind::Hollow;
        case RandomFamily::Spiral: return StairKind::Spiral;
        case RandomFamily::Descending: return StairKind::Descending;
        case RandomFamily::Debris: return StairKind::Debris;
        default: return StairKind::Ascending;
    }
}

void addFloorAt(Scene& scene, double z) { addFloor(scene, {-kFloorHalf, -kFloorHalf}, {kFloorHalf, kFloorHalf}, z); }

/// Walls, railings or nothing on each side, and stringers under open risers (flight frame T).
void addSides(Scene& scene, const Eigen::Isometry3d& T, const FlightSpec& f) {
    const double hw = 0.5 * f.width_m;
    const double x_top = f.steps * f.run_m;
    const double z_top = (f.steps + 1) * f.rise_m;
    const double x_end = x_top + (f.descending ? 0.0 : kTopLandingDepthM);
    for (double sign : {1.0, -1.0}) {
        const SideKind side = sign > 0 ? f.left : f.right;
        if (side == SideKind::Wall) {
            addLocalBox(scene, T, {0.0, sign * hw, 0.0}, {x_end, sign * (hw + 0.1), z_top + 1.0});
        } else if (side == SideKind::Railing) {
            const double y = sign * (hw - 0.03);
            addRailing(scene, T, {0.0, y, f.rise_m}, {x_top, y, z_top});
        }
        if (f.open_risers) {  // stringer: a beam under the tread ends, parallel to the nosing line
            const double y = sign * (hw + 0.025);
            addBar(scene, T, {-0.05, y, f.rise_m - 0.14}, {x_top, y, z_top - 0.12}, 0.05, 0.24);
        }
    }
}

/// Robot position in the flight frame.
V3 robotIn(const Eigen::Isometry3d& T) { return T.inverse() * V3::Zero(); }

/// Platforms, landings, lead-in steps and floors that put the flight's near end offset_steps
/// rises off the robot's floor (flight frame T, z = 0 at the flight's bottom floor).
void addLevels(Scene& scene, const Eigen::Isometry3d& T, const FlightSpec& f) {
    const int k = std::abs(f.offset_steps);
    const double hw = 0.5 * f.width_m + 0.5, rise = f.rise_m, run = f.run_m;
    const double top = (f.steps + 1) * rise, x_top = f.steps * run, L = f.landing_depth_m;
    const V3 r = robotIn(T);
    const int lead = f.offset_by_steps ? k - 1 : 0;  // treads of the steps up/down to the level
    const double wide_lo = std::min(-hw, r.y() - 4.0), wide_hi = std::max(hw, r.y() + 4.0);
    if (!f.descending) {
        if (f.offset_steps > 0) {  // raised platform under the flight, robot floor below
            addLocalBox(scene, T, {-L, -hw, -k * rise}, {x_top + kTopLandingDepthM, hw, 0.0});
            for (int j = 1; j <= lead; ++j)
                addLocalBox(scene, T, {-L - (k - j) * run, -hw, -k * rise}, {-L - (k - j - 1) * run, hw, (j - k) * rise});
            addFloorAt(scene, 0.0);
        } else if (f.offset_steps < 0) {  // robot on a raised floor, the flight starts below it
            const double front = flightFrontX(f);
            addLocalBox(scene, T, {r.x() - 4.0, r.y() - 4.0, 0.0}, {front, r.y() + 4.0, k * rise});
            for (int j = 1; j <= lead; ++j)
                addLocalBox(scene, T, {front + (j - 1) * run, r.y() - 4.0, 0.0}, {front + j * run, r.y() + 4.0, (k - j) * rise});
            addFloorAt(scene, -k * rise);
        } else {
            addFloorAt(scene, 0.0);
        }
        return;
    }
    // Descending: the robot stands on the top floor, which is the landing or k rises above it.
    const double x_land = k == 0 ? x_top : x_top + L + lead * run;
    if (k > 0) {
        addLocalBox(scene, T, {x_top, -hw, 0.0}, {x_land, hw, top});
        for (int j = 1; j <= lead; ++j)
            addLocalBox(scene, T, {x_top + L + (j - 1) * run, -hw, 0.0}, {x_top + L + j * run, hw, top + j * rise});
    }
    addLocalBox(scene, T, {x_land, wide_lo, 0.0}, {std::max(x_land + 1.0, r.x() + 4.0), wide_hi, top + k * rise});
    addFloorAt(scene, T.translation().z());
}

void addStraightFlight(Scene& scene, const FlightSpec& f, const std::string& name, StairKind kind,
                       unsigned debris_seed) {
    const Eigen::Isometry3d T = straightFlightFrame(f);
    StraightStairParams p;
    p.name = name;
    p.kind = kind;
    p.origin = T.translation();
    p.heading_deg = f.heading_deg;
    p.num_risers = f.steps + 1;
    p.rise_m = f.rise_m;
    p.run_m = f.run_m;
    p.width_m = f.width_m;
    p.open_risers = f.open_risers;
    p.tread_thickness_m = std::min(f.tread_thickness_m, f.rise_m);
    p.landing_depth_m = f.descending ? 0.3 : kTopLandingDepthM;
    p.solid_landing = !f.open_risers;
    p.landing_thickness_m = 0.15;
    p.wall_left = p.wall_right = false;
    p.debris_count = f.debris_count;
    p.debris_seed = debris_seed;
    addStraightStair(scene, p);
    addSides(scene, T, f);
    addLevels(scene, T, f);
}

void addSpiralFlight(Scene& scene, const FlightSpec& f, const std::string& name) {
    SpiralStairParams p;
    p.name = name;
    p.centre = spiralCentre(f);
    p.num_risers = f.steps + 1;
    p.rise_m = f.rise_m;
    p.column_radius_m = f.column_radius_m;
    p.outer_radius_m = spiralOuterRadius(f);
    p.step_angle_deg = f.step_angle_deg;
    p.start_angle_deg = spiralStartAngle(f) / kDeg;
    p.clockwise = f.clockwise;
    p.tread_thickness_m = f.open_risers ? std::min(f.tread_thickness_m, f.rise_m) : 0.0;
    p.landing_angle_deg = std::clamp(355.0 - f.step_angle_deg * f.steps, 30.0, 90.0);
    addSpiralStair(scene, p);
    if (f.balusters) {
        const double sign = f.clockwise ? -1.0 : 1.0;
        const double r = p.outer_radius_m - 0.04;
        for (int i = 1; i <= f.steps; ++i) {
            const double a = p.start_angle_deg * kDeg + sign * (i - 0.5) * f.step_angle_deg * kDeg;
            addBaluster(scene, Eigen::Isometry3d::Identity(),
                        p.centre + V3(r * std::cos(a), r * std::sin(a), i * f.rise_m));
        }
    }
    addFloorAt(scene, 0.0);
}
}  // namespace

Scene buildRandomScene(const RandomSceneSpec& spec) {
    Scene scene;
    scene.name = familyName(spec.family) + "_" + std::to_string(spec.index);
    for (std::size_t i = 0; i < spec.flights.size(); ++i) {
        const FlightSpec& f = spec.flights[i];
        const std::string name = "stair_" + std::to_string(i);
        const StairKind kind = i == 0 ? kindOf(spec.family) : StairKind::Ascending;
        if (f.spiral) addSpiralFlight(scene, f, name);
        else addStraightFlight(scene, f, name, kind, static_cast<unsigned>(spec.noise_seed + i));
    }
    for (const auto& extra : spec.extras) addRandomExtra(scene, extra, spec.seed, spec.index);
    std::vector<double> floors = {0.0};
    for (const auto& s : scene.truth().staircases) floors.insert(floors.end(), {s.bottom_z, s.top_z});
    std::sort(floors.begin(), floors.end());
    floors.erase(std::unique(floors.begin(), floors.end(),
                             [](double a, double b) { return std::abs(a - b) < 1e-6; }),
                 floors.end());
    scene.truth().floor_heights = floors;
    return scene;
}

}  // namespace stairmap::sim
