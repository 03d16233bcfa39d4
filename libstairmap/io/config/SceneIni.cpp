#include "io/config/SceneIni.h"

#include <sstream>

#include "io/config/IniFile.h"
#include "io/config/IniKeys.h"
#include "io/config/IniSyntax.h"
#include "io/config/SceneIniParts.h"
#include "sim/BuildingGenerator.h"
#include "sim/NegativeGenerators.h"
#include "sim/StairGenerators.h"

namespace stairmap::io {

namespace {
using detail::checked;

Eigen::Vector3d readOrigin(const IniFieldReader& ini, const std::string& s, const char* prefix) {
    const std::string p(prefix);
    return {ini.getDouble(s, p + "_x_m", 0.0), ini.getDouble(s, p + "_y_m", 0.0),
            ini.getDouble(s, p + "_z_m", 0.0)};
}

void buildStraight(const IniFieldReader& ini, StairKind kind, sim::SimulationConfig& config) {
    const std::string s = "stair";
    sim::StraightStairParams p;
    p.name = ini.getString(s, "name", "stair");
    p.kind = kind;
    p.origin = readOrigin(ini, s, "origin");
    p.heading_deg = ini.getDouble(s, "heading_deg", p.heading_deg);
    p.num_risers = ini.getInt(s, "num_risers", p.num_risers);
    p.rise_m = ini.getDouble(s, "rise_m", p.rise_m);
    p.run_m = ini.getDouble(s, "run_m", p.run_m);
    p.width_m = ini.getDouble(s, "width_m", p.width_m);
    p.open_risers = ini.getBool(s, "open_risers", kind == StairKind::Hollow);
    p.tread_thickness_m = ini.getDouble(s, "tread_thickness_m", p.tread_thickness_m);
    p.landing_depth_m = ini.getDouble(s, "landing_depth_m", kind == StairKind::Descending ? 8.0 : 2.0);
    p.solid_landing = ini.getBool(s, "solid_landing", kind != StairKind::Hollow);
    p.landing_thickness_m = ini.getDouble(s, "landing_thickness_m", p.landing_thickness_m);
    p.landing_width_m = ini.getDouble(s, "landing_width_m", kind == StairKind::Descending ? 8.0 : 0.0);
    p.wall_left = ini.getBool(s, "wall_left", p.wall_left);
    p.wall_right = ini.getBool(s, "wall_right", p.wall_right);
    p.wall_height_m = ini.getDouble(s, "wall_height_m", p.wall_height_m);
    p.debris_count = ini.getInt(s, "debris_count", kind == StairKind::Debris ? 8 : 0);
    p.debris_max_size_m = ini.getDouble(s, "debris_max_size_m", p.debris_max_size_m);
    p.debris_seed = static_cast<unsigned>(ini.getInt(s, "debris_seed", static_cast<int>(config.seed)));
    checked(ini, s, [&] { sim::addStraightStair(config.scene, p); });
    const double floor = ini.getDouble(s, "floor_extent_m", 12.0);
    sim::addFloor(config.scene, p.origin.head<2>() - Eigen::Vector2d::Constant(floor),
                  p.origin.head<2>() + Eigen::Vector2d::Constant(floor), p.origin.z());
    config.scene.truth().floor_heights = {p.origin.z(), p.origin.z() + p.num_risers * p.rise_m};
}

void buildSpiral(const IniFieldReader& ini, sim::SimulationConfig& config) {
    const std::string s = "spiral";
    sim::SpiralStairParams p;
    p.name = ini.getString(s, "name", "spiral");
    p.centre = readOrigin(ini, s, "centre");
    p.num_risers = ini.getInt(s, "num_risers", p.num_risers);
    p.rise_m = ini.getDouble(s, "rise_m", p.rise_m);
    p.column_radius_m = ini.getDouble(s, "column_radius_m", p.column_radius_m);
    p.outer_radius_m = ini.getDouble(s, "outer_radius_m", p.outer_radius_m);
    p.step_angle_deg = ini.getDouble(s, "step_angle_deg", p.step_angle_deg);
    p.start_angle_deg = ini.getDouble(s, "start_angle_deg", p.start_angle_deg);
    p.clockwise = ini.getBool(s, "clockwise", p.clockwise);
    p.tread_thickness_m = ini.getDouble(s, "tread_thickness_m", p.tread_thickness_m);
    p.landing_angle_deg = ini.getDouble(s, "landing_angle_deg", p.landing_angle_deg);
    checked(ini, s, [&] { sim::addSpiralStair(config.scene, p); });
    sim::addFloor(config.scene, p.centre.head<2>() - Eigen::Vector2d::Constant(12.0),
                  p.centre.head<2>() + Eigen::Vector2d::Constant(12.0), p.centre.z());
    config.scene.truth().floor_heights = {p.centre.z(), p.centre.z() + p.num_risers * p.rise_m};
}

void buildBuilding(const IniFieldReader& ini, sim::SimulationConfig& config) {
    const std::string s = "building";
    sim::BuildingParams p;
    p.floor_height_m = ini.getDouble(s, "floor_height_m", p.floor_height_m);
    p.num_risers = ini.getInt(s, "num_risers", p.num_risers);
    p.run_m = ini.getDouble(s, "run_m", p.run_m);
    p.width_m = ini.getDouble(s, "width_m", p.width_m);
    p.stair_b_run_m = ini.getDouble(s, "stair_b_run_m", p.stair_b_run_m);
    p.furniture = ini.getBool(s, "furniture", p.furniture);
    checked(ini, s, [&] { sim::addTwoFloorBuilding(config.scene, p); });
}

void buildNegative(const IniFieldReader& ini, const std::string& type, sim::SimulationConfig& config,
                   const std::string& s = "negative") {
    sim::NegativeParams p;
    p.type = type;
    p.origin = readOrigin(ini, s, "origin");
    p.heading_deg = ini.getDouble(s, "heading_deg", p.heading_deg);
    p.width_m = ini.getDouble(s, "width_m", p.width_m);
    p.ramp_slope_deg = ini.getDouble(s, "ramp_slope_deg", p.ramp_slope_deg);
    p.ramp_length_m = ini.getDouble(s, "ramp_length_m", p.ramp_length_m);
    p.curb_height_m = ini.getDouble(s, "curb_height_m", p.curb_height_m);
    p.stage_steps = ini.getInt(s, "stage_steps", p.stage_steps);
    p.stage_rise_m = ini.getDouble(s, "stage_rise_m", p.stage_rise_m);
    p.stage_run_m = ini.getDouble(s, "stage_run_m", p.stage_run_m);
    p.bleacher_tiers = ini.getInt(s, "bleacher_tiers", p.bleacher_tiers);
    p.bleacher_rise_m = ini.getDouble(s, "bleacher_rise_m", p.bleacher_rise_m);
    p.bleacher_run_m = ini.getDouble(s, "bleacher_run_m", p.bleacher_run_m);
    checked(ini, s, [&] { sim::addNegative(config.scene, p); });
}

/// type = negatives: several negatives in one scene (a robot walks past them). [negatives]
/// parts = <section> ...; each part section has `type` (room, ramp, curb, stage, bleachers) and
/// the [negative] keys (origin_*_m, heading_deg, ...).
void buildNegatives(const IniFieldReader& ini, sim::SimulationConfig& config) {
    std::istringstream names(ini.getString("negatives", "parts", ""));
    int count = 0;
    for (std::string part; names >> part; ++count) {
        const std::string type = ini.getString(part, "type", "");
        if (type == "room" || type == "ramp" || type == "curb" || type == "stage" || type == "bleachers")
            buildNegative(ini, type, config, part);
        else
            ini.fail(part, "type", "'" + type + "' is not a negative (room, ramp, curb, stage, bleachers)");
    }
    if (count == 0) ini.fail("negatives", "parts", "missing (names of the sections of the parts)");
}

void buildScene(const IniFieldReader& ini, const std::string& type, sim::SimulationConfig& config) {
    if (type == "ascending" || type == "descending" || type == "hollow" || type == "debris") {
        buildStraight(ini, *stairKindFromName(type), config);
        config.kind = type;
    } else if (type == "spiral") {
        buildSpiral(ini, config);
        config.kind = type;
    } else if (type == "two_floor_building") {
        buildBuilding(ini, config);
        config.kind = "ascending";
    } else if (type == "room" || type == "ramp" || type == "curb" || type == "stage" ||
               type == "bleachers") {
        buildNegative(ini, type, config);
        config.kind = "negative";
    } else if (type == "negatives") {
        buildNegatives(ini, config);
        config.kind = "negative";
    } else {
        ini.fail("scene", "type", "'" + type + "' is unknown (ascending, descending, hollow, debris, "
                 "spiral, two_floor_building, room, ramp, curb, stage, bleachers, negatives)");
    }
}
}  // namespace

sim::SimulationConfig loadSimulationConfig(const std::string& path) {
    const auto cfg = openIniFile(path);
    const std::vector<IniLine> lines = lexIniFile(path);  // malformed lines fail before anything
    const KeyRecorder recorder(*cfg);
    const IniFieldReader ini(recorder, path);
    sim::SimulationConfig config;
    const std::string type = ini.getString("scene", "type", "");
    if (type.empty()) ini.fail("scene", "type", "missing (the generator to use)");
    config.name = ini.getString("scene", "name", type);
    config.scene.name = config.name;
    config.seed = static_cast<unsigned>(ini.getInt("scene", "seed", 1));
    buildScene(ini, type, config);
    config.kind = ini.getString("scene", "kind", config.kind);
    if (!stairKindFromName(config.kind))
        ini.fail("scene", "kind", "'" + config.kind + "' is not a stair kind");
    detail::loadSensorSection(ini, config);
    detail::loadRobotRuns(ini, config);
    detail::loadCloudSection(ini, config);
    if (config.robots.empty() && config.cloud_poses.empty())
        ini.fail("trajectory", "waypoints", "the scene has neither a trajectory nor [clouds] poses");
    // Sections and keys depend on the scene type: valid are those this scene's loaders read.
    checkIniKeys(lines, recorder.keys(), path);
    return config;
}

}  // namespace stairmap::io
