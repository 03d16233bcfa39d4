#include "io/config/MapperConfig.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "io/config/DetectorConfig.h"
#include "io/config/ConfigFile.h"
#include "io/config/LandmarkConfig.h"

namespace stairmap::io {
namespace {

/// Reads typed keys of one section; every error names "[section] key".
class KeyReader {
public:
    KeyReader(const mrpt::config::CConfigFileBase& cfg, std::string section)
        : cfg_(cfg), section_(std::move(section)) {}

    std::optional<std::string> text(const char* key) const {
        // Read before asking whether the key exists: a KeyRecorder (IniKeys.h) learns the key.
        std::string t = cfg_.read_string(section_, key, "");
        if (!cfg_.keyExists(section_, key)) return std::nullopt;
        const auto not_space = [](unsigned char c) { return !std::isspace(c); };
        t.erase(t.begin(), std::find_if(t.begin(), t.end(), not_space));
        t.erase(std::find_if(t.rbegin(), t.rend(), not_space).base(), t.end());
        return t;
    }
    /// A finite number within [lo, hi].
    void number(const char* key, double& value, double lo, double hi) const {
        const auto t = text(key);
        if (!t) return;
        char* end = nullptr;
        const double v = std::strtod(t->c_str(), &end);
        if (t->empty() || *end != '\0' || !std::isfinite(v)) fail(key, *t, "is not a number");
        if (v < lo || v > hi) {
            fail(key, *t, ("is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) +
                           "]").c_str());
        }
        value = v;
    }
    void integer(const char* key, int& value, int lo, int hi) const {
        double v = value;
        number(key, v, lo, hi);
        if (v != std::floor(v)) fail(key, *text(key), "is not an integer");
        value = static_cast<int>(v);
    }
    void boolean(const char* key, bool& value) const {
        const auto t = text(key);
        if (!t) return;
        std::string l = *t;
        std::transform(l.begin(), l.end(), l.begin(), [](unsigned char c) { return std::tolower(c); });
        if (l == "true" || l == "1" || l == "yes") value = true;
        else if (l == "false" || l == "0" || l == "no") value = false;
        else fail(key, *t, "is not a boolean (true/false)");
    }
    [[noreturn]] void fail(const char* key, const std::string& t, const char* what) const {
        throw std::invalid_argument("[" + section_ + "] " + key + " = '" + t + "' " + what);
    }

private:
    const mrpt::config::CConfigFileBase& cfg_;
    std::string section_;
};

constexpr double kHuge = 1e6;

}  // namespace

pipeline::SensorParams loadSensorParams(const mrpt::config::CConfigFileBase& cfg) {
    pipeline::SensorParams p;
    const KeyReader r(cfg, "sensor");
    if (r.text("robot_height_m")) {
        r.number("robot_height_m", p.robot_height_m, -10.0, 10.0);
    } else if (const auto h = loadDetectorConfig(cfg).robot_height_m) {
        p.robot_height_m = *h;
    }
    r.boolean("floor_from_pose", p.floor_from_pose);
    if (const auto label = r.text("label_filter")) p.label_filter = *label;
    r.number("min_range_m", p.min_range_m, 0.0, kHuge);
    r.number("max_range_m", p.max_range_m, 0.0, kHuge);
    if (p.max_range_m <= p.min_range_m) {
        r.fail("max_range_m", std::to_string(p.max_range_m), "must be greater than min_range_m");
    }
    r.number("pose_x_m", p.pose_x_m, -100.0, 100.0);
    r.number("pose_y_m", p.pose_y_m, -100.0, 100.0);
    r.number("pose_z_m", p.pose_z_m, -100.0, 100.0);
    r.number("pose_yaw_deg", p.pose_yaw_deg, -360.0, 360.0);
    r.number("pose_pitch_deg", p.pose_pitch_deg, -360.0, 360.0);
    r.number("pose_roll_deg", p.pose_roll_deg, -360.0, 360.0);
    return p;
}

map::VoxelMapParams loadVoxelMapParams(const mrpt::config::CConfigFileBase& cfg) {
    map::VoxelMapParams p;
    const KeyReader r(cfg, "map");
    r.number("resolution_m", p.resolution_m, 0.005, 10.0);
    if (const auto mode = r.text("insertion_mode")) {
        if (*mode == "endpoints") p.insertion_mode = map::VoxelInsertionMode::Endpoints;
        else if (*mode == "raycast") p.insertion_mode = map::VoxelInsertionMode::RayCast;
        else r.fail("insertion_mode", *mode, "is not one of: endpoints, raycast");
    }
    r.number("max_range_m", p.max_range_m, -1.0, kHuge);
    r.integer("insert_every_n_scans", p.insert_every_n_scans, 1, 1000000);
    return p;
}

pipeline::SchedulingParams loadSchedulingParams(const mrpt::config::CConfigFileBase& cfg) {
    pipeline::SchedulingParams p;
    const KeyReader r(cfg, "scheduling");
    r.number("distance_m", p.distance_m, -1.0, kHuge);
    r.number("angle_deg", p.angle_deg, -1.0, 3600.0);
    r.number("period_s", p.period_s, -1.0, kHuge);
    r.integer("window_scans", p.window_scans, 1, 10000);
    r.number("window_s", p.window_s, 1e-6, kHuge);
    r.number("submap_radius_m", p.submap_radius_m, 0.1, 1000.0);
    r.number("submap_leaf_m", p.submap_leaf_m, -1.0, 1.0);
    r.number("max_level_slope_deg", p.max_level_slope_deg, -1.0, 89.0);
    return p;
}

pipeline::MapperParams loadMapperParams(const mrpt::config::CConfigFileBase& cfg) {
    pipeline::MapperParams p;
    p.sensor = loadSensorParams(cfg);
    p.map = loadVoxelMapParams(cfg);
    p.scheduling = loadSchedulingParams(cfg);
    p.detector = loadDetectorConfig(cfg).params;
    p.landmarks = loadLandmarkParams(cfg);
    return p;
}

pipeline::MapperParams loadMapperParams(const std::string& ini_path) {
    const auto cfg = openConfigFile(ini_path);
    try {
        return loadMapperParams(*cfg);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(ini_path + ": " + e.what());
    }
}

}  // namespace stairmap::io
