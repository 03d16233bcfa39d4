#include "io/json/StaircaseJson.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/StaircaseGeometry.h"

namespace stairmap::io {

namespace {

using nlohmann::json;

constexpr double kRadToDeg = 180.0 / M_PI;

json vec3(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

json edgeToJson(const StairEdge& e) {
    const Eigen::Matrix2d& c = e.cov_rho_theta;
    return {{"start", vec3(e.start)},
            {"end", vec3(e.end)},
            {"num_points", e.num_points},
            {"cov_rho_theta", json::array({json::array({c(0, 0), c(0, 1)}), json::array({c(1, 0), c(1, 1)})})}};
}

[[noreturn]] void fail(const std::string& field, const std::string& problem) {
    throw std::runtime_error(field + ": " + problem);
}

const json& member(const json& object, const std::string& field, const std::string& key) {
    if (!object.is_object()) fail(field, "expected an object");
    const auto it = object.find(key);
    if (it == object.end()) fail(field + "." + key, "missing");
    return *it;
}

double finiteNumber(const json& value, const std::string& field) {
    if (!value.is_number()) fail(field, "expected a number");
    const double v = value.get<double>();
    if (!std::isfinite(v)) fail(field, "expected a finite number");
    return v;
}

double nonNegative(const json& object, const std::string& field, const std::string& key) {
    const double v = finiteNumber(member(object, field, key), field + "." + key);
    if (v < 0.0) fail(field + "." + key, "must not be negative");
    return v;
}

Eigen::Vector3d vec3From(const json& value, const std::string& field) {
    if (!value.is_array() || value.size() != 3) fail(field, "expected an array of 3 finite numbers");
    Eigen::Vector3d v;
    for (int k = 0; k < 3; ++k) v[k] = finiteNumber(value[k], field + "[" + std::to_string(k) + "]");
    return v;
}

StairEdge edgeFromJson(const json& value, const std::string& field) {
    StairEdge e;
    e.start = vec3From(member(value, field, "start"), field + ".start");
    e.end = vec3From(member(value, field, "end"), field + ".end");
    if (const auto it = value.find("num_points"); it != value.end()) {
        if (!it->is_number_integer() || it->get<long long>() < 0) fail(field + ".num_points", "expected a count");
        e.num_points = it->get<int>();
    }
    if (const auto it = value.find("cov_rho_theta"); it != value.end()) {
        const std::string f = field + ".cov_rho_theta";
        if (!it->is_array() || it->size() != 2) fail(f, "expected a 2x2 array");
        for (int r = 0; r < 2; ++r) {
            if (!(*it)[r].is_array() || (*it)[r].size() != 2) fail(f, "expected a 2x2 array");
            for (int c = 0; c < 2; ++c) e.cov_rho_theta(r, c) = finiteNumber((*it)[r][c], f);
        }
    }
    return e;
}

StairDirection directionFrom(const json& value, const std::string& field) {
    if (value == "ascending") return StairDirection::Ascending;
    if (value == "descending") return StairDirection::Descending;
    fail(field, "expected \"ascending\" or \"descending\"");
}

}  // namespace

StairSide optionalSide(const nlohmann::json& object, const std::string& field,
                       const std::string& key) {
    StairSide side = StairSide::Unseen;  // files written before the field existed
    const auto it = object.find(key);
    if (it == object.end()) return side;
    if (!it->is_string() || !stairSideFromName(it->get<std::string>(), side))
        fail(field + "." + key, "expected \"wall\", \"open\" or \"unseen\"");
    return side;
}

nlohmann::json toJson(const Staircase& s) {
    json steps = json::array();
    for (const StairEdge& e : s.steps) steps.push_back(edgeToJson(e));
    return {{"direction", s.direction == StairDirection::Ascending ? "ascending" : "descending"},
            {"num_steps", s.steps.size()},
            {"step_height", s.step_height},
            {"step_depth", s.step_depth},
            {"step_width", s.step_width},
            {"slope_deg", s.slope_rad * kRadToDeg},
            {"location", vec3(s.location)},
            {"heading_deg", s.heading_rad * kRadToDeg},
            {"left_side", stairSideName(s.left_side)},
            {"right_side", stairSideName(s.right_side)},
            {"steps", steps}};
}

Staircase staircaseFromJson(const nlohmann::json& j) {
    const std::string f = "staircase";
    Staircase s;
    s.direction = directionFrom(member(j, f, "direction"), f + ".direction");
    s.step_height = nonNegative(j, f, "step_height");
    s.step_depth = nonNegative(j, f, "step_depth");
    s.step_width = nonNegative(j, f, "step_width");
    s.slope_rad = finiteNumber(member(j, f, "slope_deg"), f + ".slope_deg") / kRadToDeg;
    s.location = vec3From(member(j, f, "location"), f + ".location");
    s.heading_rad = finiteNumber(member(j, f, "heading_deg"), f + ".heading_deg") / kRadToDeg;
    s.left_side = optionalSide(j, f, "left_side");
    s.right_side = optionalSide(j, f, "right_side");
    const json& steps = member(j, f, "steps");
    if (!steps.is_array()) fail(f + ".steps", "expected an array");
    for (std::size_t i = 0; i < steps.size(); ++i) {
        s.steps.push_back(edgeFromJson(steps[i], f + ".steps[" + std::to_string(i) + "]"));
    }
    if (const auto it = j.find("num_steps"); it != j.end()) {
        if (!it->is_number_integer() || it->get<long long>() != static_cast<long long>(s.steps.size())) {
            fail(f + ".num_steps", "must equal the number of entries in steps (" + std::to_string(s.steps.size()) + ")");
        }
    }
    return s;
}

nlohmann::json detectionToJson(const DetectionResult& result, double time_ms) {
    json staircases = json::array();
    for (const Staircase& s : result.staircases) {
        json one = toJson(s);
        // Relative to the robot's floor: 0 for a flight off it, else the landing or platform
        // height the flight starts from (a detection property: maps keep absolute heights).
        if (!s.steps.empty()) one["start_z"] = flightStartZ(s) - result.floor_z;
        staircases.push_back(std::move(one));
    }
    return {{"staircases", staircases},
            {"time_ms", time_ms},
            {"floor_z", result.floor_z},
            {"floor_estimated", result.floor_estimated}};
}

}  // namespace stairmap::io
