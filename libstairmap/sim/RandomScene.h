#pragma once
// Randomised benchmark scenes (issue 10): a scene description drawn from wide distributions of
// stairs, negatives and sensors with a seed, then built into solids (RandomSceneBuild.cpp) and
// observed by the drawn sensor (RandomCloud.h). Drawing does no ray casting, so the distributions
// can be checked on thousands of descriptions quickly.
//
// Frame of a description: the robot's gravity-aligned frame at the final pose, x forward, y left,
// z up, its floor at z = 0 (the robot origin is base_height_m above it). Lengths in metres, angles
// in degrees.

#include <cstdint>
#include <string>
#include <vector>

namespace stairmap::sim {

/// Table rows of the benchmark (the paper's five kinds plus scenes with no staircase).
enum class RandomFamily { Ascending, Hollow, Spiral, Descending, Debris, Negative };
/// How the cloud is made.
enum class RandomSensorKind { LevelLidar, PitchedLidar, DepthCamera, ElevationMap };
/// What bounds a straight flight's side.
enum class SideKind { Wall, Open, Railing };

std::string familyName(RandomFamily family);      ///< "ascending", ..., "negative"
std::string sensorKindName(RandomSensorKind kind);  ///< "level_lidar", ..., "elevation_map"
std::string sideKindName(SideKind side);          ///< "wall", "open", "railing"

/// The ranges the generator draws from (the distributions); the tests check draws against
/// these same numbers.
struct RandomRanges {
    double rise_min_m = 0.10, rise_max_m = 0.22;       ///< [m] straight and spiral rise
    double run_min_m = 0.22, run_max_m = 0.40;         ///< [m] straight run; spiral run at mid radius
    double width_min_m = 0.6, width_max_m = 2.5;       ///< [m] straight width
    double spiral_width_min_m = 0.6, spiral_width_max_m = 1.4;  ///< [m] tread length (radial)
    int steps_min = 3, steps_max = 16;                 ///< treads below the top landing (risers - 1)
    double distance_min_m = 0.5, distance_max_m = 8.0; ///< [m] robot to the first edge (xy)
    double depth_distance_max_m = 4.0;                 ///< [m] same, depth cameras / elevation maps
    double column_min_m = 0.05, column_max_m = 0.30;   ///< [m] spiral column radius
    double lidar_pitch_min_deg = 15, lidar_pitch_max_deg = 30;   ///< pitched-down LiDARs
    double camera_pitch_min_deg = 25, camera_pitch_max_deg = 45; ///< depth cameras
    int scans_min = 1, scans_max = 5;                  ///< scans accumulated into one cloud
    double cell_min_m = 0.02, cell_max_m = 0.04;       ///< [m] elevation-map cell size
    int offset_steps_max = 3;                          ///< platform/landing: 1..3 rises off the floor
    double ramp_min_deg = 5, ramp_max_deg = 15;        ///< [deg] ramp slope
    double bleacher_rise_min_m = 0.36, bleacher_rise_max_m = 0.50;  ///< [m] bleacher tier height
};

/// One flight of stairs.
struct FlightSpec {
    bool spiral = false;
    bool descending = false;      ///< the robot stands on its top floor (seen going down)
    int steps = 8;                ///< treads below the top landing; risers = steps + 1
    double rise_m = 0.17, run_m = 0.28, width_m = 1.2;
    double distance_m = 2.0;      ///< [m] robot to the first edge it meets (foot or top nosing)
    double bearing_deg = 0.0;     ///< [deg] direction from the robot to that edge
    double heading_deg = 0.0;     ///< [deg] direction of ascent
    SideKind left = SideKind::Wall, right = SideKind::Wall;  ///< sides, looking up the flight
    bool open_risers = false;     ///< floating treads between stringers
    double tread_thickness_m = 0.04;
    int debris_count = 0;
    /// Rises between the robot's floor and the flight's end nearest to it (its foot when seen
    /// ascending, its head when descending): > 0 above the floor, < 0 below, 0 on it.
    int offset_steps = 0;
    bool offset_by_steps = false; ///< reach that level by |offset| steps (a landing), else a platform
    double landing_depth_m = 1.0; ///< [m] platform / landing depth in front of the flight
    // --- spiral only
    double column_radius_m = 0.12;
    double step_angle_deg = 25.0; ///< [deg] turn per tread
    bool clockwise = false;
    bool balusters = false;
    int turn_total_deg() const { return static_cast<int>(step_angle_deg * steps); }
};

/// A scene without a staircase (or furniture added to any scene).
struct NegativeSpec {
    std::string type = "room";  ///< room | ramp_up | ramp_down | curb | stage | bleachers | furniture
    double distance_m = 2.0, bearing_deg = 0.0, heading_deg = 0.0;
    double width_m = 3.0;
    double slope_deg = 10.0;    ///< ramps
    double height_m = 0.15;     ///< curb height, stage/bleacher rise
    double run_m = 0.3;         ///< stage/bleacher tier depth
    int tiers = 2;              ///< stage steps (1..2), bleacher tiers
};

struct SensorSpec {
    RandomSensorKind kind = RandomSensorKind::LevelLidar;
    std::string model = "vlp16";  ///< vlp16 | hdl32 | os1_64 | os0_128 | depth_camera | elevation_map
    double base_height_m = 0.45;  ///< [m] robot origin above its floor
    double mount_height_m = 0.2;  ///< [m] sensor above the robot origin
    double pitch_deg = 0.0;       ///< [deg] downward pitch of the sensor
    int scans = 3;                ///< scans along the path
    double path_length_m = 0.5;   ///< [m] the scans are taken along the last metres before the pose
    double tilt_std_deg = 1.5;    ///< [deg] body roll/pitch per scan
    double cell_m = 0.03;         ///< [m] elevation map cell
};

struct RandomSceneSpec {
    std::uint64_t seed = 1;
    int index = 0;
    RandomFamily family = RandomFamily::Ascending;
    SensorSpec sensor;
    std::vector<FlightSpec> flights;     ///< empty for negatives
    std::vector<NegativeSpec> extras;    ///< the negative feature, and furniture in any scene
    unsigned noise_seed = 1;             ///< sensor noise of this scene
};

/// Generator version: part of cached sets' names, bump when the distributions change.
constexpr int kRandomGeneratorVersion = 1;

/// Draws the description of scene `index` of the set `seed` (deterministic; no ray casting).
/// `attempt` > 0 redraws a scene whose flight was only partly visible (see RandomCloud.h).
RandomSceneSpec drawRandomScene(std::uint64_t seed, int index, int attempt = 0,
                                const RandomRanges& ranges = {});

}  // namespace stairmap::sim
