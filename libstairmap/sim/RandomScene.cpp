#include "sim/RandomScene.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "sim/RandomDraw.h"
#include "sim/RandomFlightGeometry.h"

namespace stairmap::sim {

std::string familyName(RandomFamily f) {
    switch (f) {
        case RandomFamily::Ascending: return "ascending";
        case RandomFamily::Hollow: return "hollow";
        case RandomFamily::Spiral: return "spiral";
        case RandomFamily::Descending: return "descending";
        case RandomFamily::Debris: return "debris";
        case RandomFamily::Negative: return "negative";
    }
    return "negative";
}

std::string sensorKindName(RandomSensorKind k) {
    switch (k) {
        case RandomSensorKind::LevelLidar: return "level_lidar";
        case RandomSensorKind::PitchedLidar: return "pitched_lidar";
        case RandomSensorKind::DepthCamera: return "depth_camera";
        case RandomSensorKind::ElevationMap: return "elevation_map";
    }
    return "level_lidar";
}

std::string sideKindName(SideKind s) {
    switch (s) {
        case SideKind::Wall: return "wall";
        case SideKind::Open: return "open";
        case SideKind::Railing: return "railing";
    }
    return "open";
}

namespace {

// Family shares of a set (ascending, hollow, spiral, descending, debris, negative).
const std::vector<double> kFamilyWeights = {0.20, 0.12, 0.14, 0.18, 0.12, 0.24};
// Sensor kinds (level LiDAR, pitched LiDAR, depth camera, elevation map).
const std::vector<double> kSensorWeights = {0.35, 0.30, 0.15, 0.20};

SensorSpec drawSensor(RandomDraw& d, const RandomRanges& r) {
    SensorSpec s;
    s.kind = static_cast<RandomSensorKind>(d.pick(kSensorWeights));
    s.base_height_m = d.uniform(0.3, 0.6);
    s.scans = d.integer(r.scans_min, r.scans_max);
    s.path_length_m = s.scans > 1 ? d.uniform(0.0, 1.0) : 0.0;
    s.tilt_std_deg = d.uniform(0.0, 3.0);
    switch (s.kind) {
        case RandomSensorKind::LevelLidar:
        case RandomSensorKind::PitchedLidar: {
            static const std::vector<std::string> models = {"vlp16", "hdl32", "os1_64", "os0_128"};
            s.model = models[d.integer(0, 3)];
            s.mount_height_m = d.uniform(0.1, 0.4);
            if (s.kind == RandomSensorKind::PitchedLidar)
                s.pitch_deg = d.uniform(r.lidar_pitch_min_deg, r.lidar_pitch_max_deg);
            break;
        }
        case RandomSensorKind::DepthCamera:
            s.model = "depth_camera";
            s.mount_height_m = d.uniform(0.05, 0.4);
            s.pitch_deg = d.uniform(r.camera_pitch_min_deg, r.camera_pitch_max_deg);
            break;
        case RandomSensorKind::ElevationMap:
            s.model = "elevation_map";
            s.scans = 1;
            s.path_length_m = 0.0;
            s.cell_m = d.uniform(r.cell_min_m, r.cell_max_m);
            break;
    }
    return s;
}

/// Bearing of a feature the sensor can plausibly see: anywhere for level LiDARs and elevation
/// maps, the front two thirds for pitched LiDARs, inside the field of view for depth cameras.
double drawBearing(RandomDraw& d, const SensorSpec& s) {
    switch (s.kind) {
        case RandomSensorKind::PitchedLidar: return d.uniform(-120.0, 120.0);
        case RandomSensorKind::DepthCamera: return d.uniform(-30.0, 30.0);
        default: return d.uniform(-180.0, 180.0);
    }
}

double drawDistance(RandomDraw& d, const SensorSpec& s, const RandomRanges& r, double at_least = 0) {
    const bool near = s.kind == RandomSensorKind::DepthCamera || s.kind == RandomSensorKind::ElevationMap;
    const double hi = near ? r.depth_distance_max_m : r.distance_max_m;
    return d.uniform(std::max(r.distance_min_m, at_least), hi);
}

SideKind drawSide(RandomDraw& d, bool hollow) {
    return static_cast<SideKind>(d.pick(hollow ? std::vector<double>{0.2, 0.4, 0.4}
                                               : std::vector<double>{0.4, 0.3, 0.3}));
}

FlightSpec drawStraight(RandomDraw& d, RandomFamily family, const SensorSpec& s,
                        const RandomRanges& r) {
    FlightSpec f;
    f.descending = family == RandomFamily::Descending;
    f.steps = d.integer(r.steps_min, r.steps_max);
    f.rise_m = d.uniform(r.rise_min_m, r.rise_max_m);
    f.run_m = d.uniform(r.run_min_m, r.run_max_m);
    f.width_m = d.uniform(r.width_min_m, r.width_max_m);
    const bool hollow = family == RandomFamily::Hollow;
    f.left = drawSide(d, hollow);
    f.right = drawSide(d, hollow);
    f.open_risers = hollow || (f.descending && d.chance(0.25));
    f.tread_thickness_m = d.uniform(0.03, 0.06);
    f.debris_count = family == RandomFamily::Debris ? d.integer(3, 10) : 0;
    if (d.chance(0.25)) {  // a platform or landing off the robot's floor
        const int k = d.integer(1, r.offset_steps_max);
        f.offset_steps = f.descending || d.chance(0.5) ? -k : k;
        f.offset_by_steps = d.chance(0.5);
    }
    f.landing_depth_m = d.uniform(0.9, 1.6);
    const double needed = f.offset_steps != 0 ? f.landing_depth_m + r.offset_steps_max * r.run_max_m + 0.5 : 0.0;
    f.distance_m = drawDistance(d, s, r, needed);
    f.bearing_deg = drawBearing(d, s);
    // Ascent away from the robot (ascending) or towards it (descending), up to 60 deg oblique,
    // as long as the robot stays clear of the flight's solids.
    const double straight_on = f.bearing_deg + (f.descending ? 180.0 : 0.0);
    for (int tries = 0; tries < 20; ++tries) {
        f.heading_deg = straight_on + d.uniform(-60.0, 60.0);
        if (robotClear(f)) return f;
    }
    f.heading_deg = straight_on;
    return f;
}

FlightSpec drawSpiral(RandomDraw& d, const SensorSpec& s, const RandomRanges& r) {
    FlightSpec f;
    f.spiral = true;
    f.rise_m = d.uniform(r.rise_min_m, r.rise_max_m);
    f.column_radius_m = d.uniform(r.column_min_m, r.column_max_m);
    f.clockwise = d.chance(0.5);
    f.open_risers = d.chance(0.5);
    f.tread_thickness_m = d.uniform(0.03, 0.06);
    f.balusters = d.chance(0.5);
    constexpr double kRad = M_PI / 180.0;
    // Treads turn more than half a turn and less than 300 deg with the run at mid radius in range;
    // narrow spirals around thin columns cannot do that with many steps, so redraw the width.
    for (int tries = 0;; ++tries) {
        f.width_m = d.uniform(r.spiral_width_min_m, r.spiral_width_max_m);
        const double r_mid = f.column_radius_m + 0.5 * f.width_m;
        const double lo = 2.0 * std::asin(r.run_min_m / (2.0 * r_mid)) / kRad;
        const double hi = 2.0 * std::asin(std::min(1.0, r.run_max_m / (2.0 * r_mid))) / kRad;
        const int n_lo = std::max(r.steps_min, static_cast<int>(std::ceil(185.0 / hi)));
        const int n_hi = std::min(r.steps_max, static_cast<int>(std::floor(300.0 / lo)));
        if (n_lo > n_hi && tries < 50) continue;
        f.steps = d.integer(n_lo, std::max(n_lo, n_hi));
        const double a_lo = std::max(lo, 185.0 / f.steps);
        const double a_hi = std::max(a_lo, std::min(hi, 300.0 / f.steps));
        f.step_angle_deg = d.uniform(a_lo, a_hi);
        f.run_m = 2.0 * r_mid * std::sin(0.5 * f.step_angle_deg * kRad);
        break;
    }
    f.distance_m = drawDistance(d, s, r);
    f.bearing_deg = drawBearing(d, s);
    f.heading_deg = d.uniform(-90.0, 90.0);  // first nosing's angle, relative to facing the robot
    return f;
}

NegativeSpec drawNegative(RandomDraw& d, const SensorSpec& s, const RandomRanges& r) {
    static const std::vector<std::string> types = {"room", "ramp_up", "ramp_down", "curb",
                                                   "stage", "bleachers", "furniture"};
    NegativeSpec n;
    n.type = types[d.integer(0, static_cast<int>(types.size()) - 1)];
    n.distance_m = drawDistance(d, s, r);
    n.bearing_deg = drawBearing(d, s);
    n.heading_deg = n.bearing_deg + (n.type == "ramp_down" ? 180.0 : 0.0) + d.uniform(-45.0, 45.0);
    n.width_m = d.uniform(1.0, 4.0);
    n.slope_deg = d.uniform(r.ramp_min_deg, r.ramp_max_deg);
    n.run_m = d.uniform(2.0, 5.0);  // ramp length
    if (n.type == "curb") n.height_m = d.uniform(0.08, 0.25);
    if (n.type == "stage") {
        n.tiers = d.integer(1, 2);
        n.height_m = d.uniform(r.rise_min_m, r.rise_max_m);
        n.run_m = d.uniform(r.run_min_m, r.run_max_m);
    }
    if (n.type == "bleachers") {
        n.tiers = d.integer(3, 6);
        n.height_m = d.uniform(r.bleacher_rise_min_m, r.bleacher_rise_max_m);
        n.run_m = d.uniform(0.6, 0.9);
    }
    if (n.type == "room" || n.type == "furniture") n.tiers = d.integer(2, 5);  // pieces of furniture
    return n;
}
}  // namespace

RandomSceneSpec drawRandomScene(std::uint64_t seed, int index, int attempt, const RandomRanges& r) {
    RandomDraw d(seed, static_cast<std::uint64_t>(index), static_cast<std::uint64_t>(attempt));
    RandomSceneSpec spec;
    spec.seed = seed;
    spec.index = index;
    // The family depends on the index only, so redrawing a scene keeps its table row.
    RandomDraw family_draw(seed, static_cast<std::uint64_t>(index), 0xfa111e5ULL);
    spec.family = static_cast<RandomFamily>(family_draw.pick(kFamilyWeights));
    spec.sensor = drawSensor(d, r);
    spec.noise_seed = static_cast<unsigned>(d.integer(1, 1 << 30));
    switch (spec.family) {
        case RandomFamily::Negative: spec.extras.push_back(drawNegative(d, spec.sensor, r)); break;
        case RandomFamily::Spiral: spec.flights.push_back(drawSpiral(d, spec.sensor, r)); break;
        default: {
            spec.flights.push_back(drawStraight(d, spec.family, spec.sensor, r));
            const auto& first = spec.flights.front();
            // A second flight in view (placed clear of the first by the builder, or dropped).
            if (!first.descending && first.offset_steps == 0 && d.chance(0.2)) {
                for (int tries = 0; tries < 20; ++tries) {
                    FlightSpec second = drawStraight(d, RandomFamily::Ascending, spec.sensor, r);
                    if (second.offset_steps != 0) continue;
                    if (robotClear(second) && !footprintsOverlap(first, second, 0.5)) {
                        spec.flights.push_back(second);
                        break;
                    }
                }
            }
        }
    }
    double nearest = 1e9;
    for (const auto& f : spec.flights) nearest = std::min(nearest, f.distance_m);
    for (const auto& n : spec.extras) nearest = std::min(nearest, n.distance_m);
    // The scans are taken along the path that ends at the robot: never over the feature.
    spec.sensor.path_length_m = std::min(spec.sensor.path_length_m, 0.5 * nearest);
    return spec;
}

}  // namespace stairmap::sim
