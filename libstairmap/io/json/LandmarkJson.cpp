#include "io/json/LandmarkJson.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "io/json/JsonFields.h"
#include "io/json/LandmarkPlausibility.h"
#include "io/json/StaircaseJson.h"
#include "io/json/LandmarkParamsJson.h"

namespace stairmap::io {
namespace {

using nlohmann::json;
namespace jf = json_fields;
constexpr double kRadToDeg = 180.0 / M_PI;

json stepToJson(const StairEdge& e, int observations) {
    return {{"start", jf::toJson(e.start)},       {"end", jf::toJson(e.end)},
            {"num_points", e.num_points},         {"observations", observations},
            {"cov_rho_theta", jf::toJson(e.cov_rho_theta)}};
}

json landmarkToJson(const StaircaseLandmark& lm) {
    const Staircase& s = lm.stairs;
    json steps = json::array();
    for (std::size_t i = 0; i < s.steps.size(); ++i) {
        steps.push_back(stepToJson(s.steps[i], lm.step_observations.at(i)));
    }
    return {{"id", lm.id},
            {"confirmed", lm.confirmed},
            {"observations", lm.observations},
            {"first_seen_s", lm.first_seen_s},
            {"last_seen_s", lm.last_seen_s},
            {"bottom_observed", lm.bottom_observed},
            {"top_observed", lm.top_observed},
            {"bottom_floor", lm.bottom_floor},
            {"top_floor", lm.top_floor},
            {"direction", "ascending"},
            {"num_steps", s.steps.size()},
            {"step_height", s.step_height},
            {"step_depth", s.step_depth},
            {"step_width", s.step_width},
            {"slope_deg", s.slope_rad * kRadToDeg},
            {"slope_rad", s.slope_rad},
            {"location", jf::toJson(s.location)},
            {"heading_deg", s.heading_rad * kRadToDeg},
            {"heading_rad", s.heading_rad},
            {"left_side", stairSideName(s.left_side)},
            {"right_side", stairSideName(s.right_side)},
            {"steps", steps}};
}

json floorLevelToJson(const Floor& f) {
    return {{"id", f.id},
            {"z", f.z},
            {"robot_samples", f.robot_samples},
            {"robot_z_sum", f.robot_z_sum},
            {"staircase_ends", f.staircase_ends},
            {"end_z_sum", f.end_z_sum}};
}

json reportedFloors(const LandmarkMapState& state, const LandmarkParams& params) {
    std::vector<Floor> floors;
    for (const Floor& f : state.floor_levels) {
        if (f.robot_samples >= params.floor_min_robot_samples || f.staircase_ends > 0)
            floors.push_back(f);
    }
    std::sort(floors.begin(), floors.end(), [](const Floor& a, const Floor& b) { return a.z < b.z; });
    json out = json::array();
    for (const Floor& f : floors) {
        out.push_back({{"id", f.id},
                       {"z", f.z},
                       {"robot_samples", f.robot_samples},
                       {"staircase_ends", f.staircase_ends}});
    }
    return out;
}

StairEdge stepFromJson(const json& j, const std::string& path, int& observations) {
    StairEdge e;
    e.start = jf::vector3(jf::member(j, "start", path), path + ".start");
    e.end = jf::vector3(jf::member(j, "end", path), path + ".end");
    e.num_points = jf::integer(jf::member(j, "num_points", path), path + ".num_points");
    e.cov_rho_theta = jf::matrix2(jf::member(j, "cov_rho_theta", path), path + ".cov_rho_theta");
    observations = jf::integer(jf::member(j, "observations", path), path + ".observations");
    if (observations < 1) throw std::runtime_error(path + ".observations: must be >= 1");
    return e;
}

double numberField(const json& j, const char* key, const std::string& path) {
    return jf::finiteNumber(jf::member(j, key, path), path + "." + key);
}

int intField(const json& j, const char* key, const std::string& path) {
    return jf::integer(jf::member(j, key, path), path + "." + key);
}

StaircaseLandmark landmarkFromJson(const json& j, const std::string& path) {
    StaircaseLandmark lm;
    lm.id = intField(j, "id", path);
    lm.confirmed = jf::boolean(jf::member(j, "confirmed", path), path + ".confirmed");
    lm.observations = intField(j, "observations", path);
    lm.first_seen_s = numberField(j, "first_seen_s", path);
    lm.last_seen_s = numberField(j, "last_seen_s", path);
    lm.bottom_observed = jf::boolean(jf::member(j, "bottom_observed", path), path + ".bottom_observed");
    lm.top_observed = jf::boolean(jf::member(j, "top_observed", path), path + ".top_observed");
    lm.bottom_floor = intField(j, "bottom_floor", path);
    lm.top_floor = intField(j, "top_floor", path);
    if (jf::text(jf::member(j, "direction", path), path + ".direction") != "ascending")
        throw std::runtime_error(path + ".direction: must be \"ascending\" (canonical form)");
    Staircase& s = lm.stairs;
    s.step_height = numberField(j, "step_height", path);
    s.step_depth = numberField(j, "step_depth", path);
    s.step_width = numberField(j, "step_width", path);
    s.slope_rad = numberField(j, "slope_rad", path);
    s.heading_rad = numberField(j, "heading_rad", path);
    s.location = jf::vector3(jf::member(j, "location", path), path + ".location");
    s.left_side = optionalSide(j, path, "left_side");  // absent in maps written before them
    s.right_side = optionalSide(j, path, "right_side");
    const json& steps = jf::arrayMember(j, "steps", path);
    if (steps.empty()) throw std::runtime_error(path + ".steps: must not be empty");
    for (std::size_t i = 0; i < steps.size(); ++i) {
        int obs = 0;
        s.steps.push_back(stepFromJson(steps[i], path + ".steps[" + std::to_string(i) + "]", obs));
        lm.step_observations.push_back(obs);
    }
    if (intField(j, "num_steps", path) != static_cast<int>(steps.size()))
        throw std::runtime_error(path + ".num_steps: does not match the number of steps");
    if (lm.observations < 1) throw std::runtime_error(path + ".observations: must be >= 1");
    return lm;
}

Floor floorLevelFromJson(const json& j, const std::string& path) {
    Floor f;
    f.id = intField(j, "id", path);
    f.z = numberField(j, "z", path);
    f.robot_samples = intField(j, "robot_samples", path);
    f.robot_z_sum = numberField(j, "robot_z_sum", path);
    f.staircase_ends = intField(j, "staircase_ends", path);
    f.end_z_sum = numberField(j, "end_z_sum", path);
    if (f.robot_samples < 0 || f.staircase_ends < 0)
        throw std::runtime_error(path + ": negative sample count");
    return f;
}

json transitToJson(const FloorTransit& t) {
    json path = json::array();
    for (const Eigen::Vector3d& p : t.floor_path) path.push_back(jf::toJson(p));
    return {{"stamp_s", t.stamp_s}, {"floor_path", path}};
}

FloorTransit transitFromJson(const json& j, const std::string& path) {
    FloorTransit t;
    t.stamp_s = numberField(j, "stamp_s", path);
    const json& points = jf::arrayMember(j, "floor_path", path);
    if (points.size() < 3) throw std::runtime_error(path + ".floor_path: needs at least 3 points");
    for (std::size_t i = 0; i < points.size(); ++i) {
        t.floor_path.push_back(
            jf::vector3(points[i], path + ".floor_path[" + std::to_string(i) + "]"));
    }
    return t;
}

void readTransits(const json& c, LandmarkMapState& state) {
    // Optional: version-1 documents written before floor transits existed have none.
    if (!c.is_object() || !c.contains("transits")) return;
    const json& transits = jf::arrayMember(c, "transits", "continuation");
    for (std::size_t i = 0; i < transits.size(); ++i) {
        state.transits.push_back(
            transitFromJson(transits[i], "continuation.transits[" + std::to_string(i) + "]"));
    }
}

void readContinuation(const json& c, LandmarkMapState& state) {
    const std::string path = "continuation";
    state.next_landmark_id = intField(c, "next_landmark_id", path);
    state.next_floor_id = intField(c, "next_floor_id", path);
    const json& levels = jf::arrayMember(c, "floor_levels", path);
    for (std::size_t i = 0; i < levels.size(); ++i) {
        state.floor_levels.push_back(
            floorLevelFromJson(levels[i], path + ".floor_levels[" + std::to_string(i) + "]"));
    }
    const json& absorbed = jf::arrayMember(c, "absorbed", path);
    for (std::size_t i = 0; i < absorbed.size(); ++i) {
        const std::string p = path + ".absorbed[" + std::to_string(i) + "]";
        state.absorbed[intField(absorbed[i], "id", p)] = intField(absorbed[i], "into", p);
    }
    readTransits(c, state);
}

void checkHeader(const json& doc) {
    const int version = jf::integer(jf::member(doc, "version", ""), "version");
    if (version != kLandmarkJsonVersion) {
        throw std::runtime_error("version: unsupported version " + std::to_string(version) +
                                 " (this build reads version " +
                                 std::to_string(kLandmarkJsonVersion) + ")");
    }
    if (jf::text(jf::member(doc, "frame", ""), "frame") != "world")
        throw std::runtime_error("frame: must be \"world\"");
    jf::arrayMember(doc, "floors", "");
}

/// The reported floors are recomputed on the next save, but a loaded document must still be sane.
void checkReportedFloors(const json& doc) {
    const json& floors = jf::arrayMember(doc, "floors", "");
    for (std::size_t i = 0; i < floors.size(); ++i) {
        const std::string path = "floors[" + std::to_string(i) + "]";
        checkWorldZ(numberField(floors[i], "z", path), path + ".z");
    }
}

}  // namespace

json landmarkStateToJson(const LandmarkMapState& state, const LandmarkParams& params) {
    json staircases = json::array();
    for (const StaircaseLandmark& lm : state.staircases) staircases.push_back(landmarkToJson(lm));
    json levels = json::array();
    for (const Floor& f : state.floor_levels) levels.push_back(floorLevelToJson(f));
    json absorbed = json::array();
    for (const auto& [gone, into] : state.absorbed) absorbed.push_back({{"id", gone}, {"into", into}});
    json transits = json::array();
    for (const FloorTransit& t : state.transits) transits.push_back(transitToJson(t));
    return {{"version", kLandmarkJsonVersion},
            {"frame", "world"},
            {"generator", "stairmap"},
            {"floors", reportedFloors(state, params)},
            {"staircases", staircases},
            {"continuation",
             {{"next_landmark_id", state.next_landmark_id},
              {"next_floor_id", state.next_floor_id},
              {"floor_levels", levels},
              {"absorbed", absorbed},
              {"transits", transits}}},
            {"params", landmarkParamsToJson(params)}};
}

LandmarkMapState landmarkStateFromJson(const json& doc, LandmarkParams* params_out) {
    checkHeader(doc);
    LandmarkMapState state;
    const json& staircases = jf::arrayMember(doc, "staircases", "");
    for (std::size_t i = 0; i < staircases.size(); ++i) {
        state.staircases.push_back(
            landmarkFromJson(staircases[i], "staircases[" + std::to_string(i) + "]"));
    }
    readContinuation(jf::member(doc, "continuation", ""), state);
    const LandmarkParams params = landmarkParamsFromJson(jf::member(doc, "params", ""), "params");
    checkReportedFloors(doc);
    checkLandmarkPlausibility(state);
    if (params_out) *params_out = params;
    return state;
}

}  // namespace stairmap::io
