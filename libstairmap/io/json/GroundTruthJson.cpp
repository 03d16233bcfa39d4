#include "io/json/GroundTruthJson.h"

#include "io/system/InputFile.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace stairmap::io {

namespace {
using nlohmann::json;

json vec3(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

[[noreturn]] void fail(const std::string& source, const std::string& what) {
    throw std::runtime_error(source + ": " + what);
}

const json& member(const json& obj, const char* key, const std::string& source, const std::string& where) {
    if (!obj.is_object() || !obj.contains(key)) fail(source, where + ": missing key '" + key + "'");
    return obj.at(key);
}

double number(const json& obj, const char* key, const std::string& source, const std::string& where) {
    const json& v = member(obj, key, source, where);
    if (!v.is_number() || !std::isfinite(v.get<double>()))
        fail(source, where + "." + key + ": must be a finite number");
    return v.get<double>();
}

Eigen::Vector3d point(const json& v, const std::string& source, const std::string& where) {
    if (!v.is_array() || v.size() != 3) fail(source, where + ": must be [x, y, z]");
    Eigen::Vector3d p;
    for (int i = 0; i < 3; ++i) {
        if (!v[i].is_number() || !std::isfinite(v[i].get<double>()))
            fail(source, where + ": must hold finite numbers");
        p[i] = v[i].get<double>();
    }
    return p;
}

json staircaseToJson(const StaircaseTruth& s) {
    json nosings = json::array();
    for (const auto& n : s.nosings) nosings.push_back({{"start", vec3(n.start)}, {"end", vec3(n.end)}});
    json j = {{"name", s.name},         {"kind", stairKindName(s.kind)},
              {"num_risers", s.num_risers}, {"rise_m", s.rise_m},
              {"run_m", s.run_m},       {"width_m", s.width_m},
              {"bottom_z", s.bottom_z}, {"top_z", s.top_z},
              {"nosings", nosings}};
    j["seen_as"] = s.seen_as ? json(*s.seen_as == StairDirection::Ascending ? "ascending" : "descending")
                             : json(nullptr);
    return j;
}

StaircaseTruth staircaseFromJson(const json& j, const std::string& source, const std::string& where) {
    StaircaseTruth s;
    const json& name = member(j, "name", source, where);
    if (!name.is_string()) fail(source, where + ".name: must be a string");
    s.name = name.get<std::string>();
    const json& kind = member(j, "kind", source, where);
    const auto k = kind.is_string() ? stairKindFromName(kind.get<std::string>()) : std::nullopt;
    if (!k) fail(source, where + ".kind: must be ascending|hollow|spiral|descending|debris");
    s.kind = *k;
    s.rise_m = number(j, "rise_m", source, where);
    s.run_m = number(j, "run_m", source, where);
    s.width_m = number(j, "width_m", source, where);
    s.bottom_z = number(j, "bottom_z", source, where);
    s.top_z = number(j, "top_z", source, where);
    s.num_risers = static_cast<int>(number(j, "num_risers", source, where));
    const json& nosings = member(j, "nosings", source, where);
    if (!nosings.is_array()) fail(source, where + ".nosings: must be an array");
    for (std::size_t i = 0; i < nosings.size(); ++i) {
        const std::string w = where + ".nosings[" + std::to_string(i) + "]";
        s.nosings.push_back({point(member(nosings[i], "start", source, w), source, w + ".start"),
                             point(member(nosings[i], "end", source, w), source, w + ".end")});
    }
    if (j.contains("seen_as") && j["seen_as"].is_string()) {
        const auto seen = j["seen_as"].get<std::string>();
        if (seen == "ascending") s.seen_as = StairDirection::Ascending;
        else if (seen == "descending") s.seen_as = StairDirection::Descending;
        else fail(source, where + ".seen_as: must be ascending, descending or null");
    }
    return s;
}
}  // namespace

json groundTruthToJson(const SceneTruth& truth) {
    json stairs = json::array();
    for (const auto& s : truth.staircases) stairs.push_back(staircaseToJson(s));
    json j = {{"format", "stairmap-gt"}, {"version", 1},          {"frame", truth.frame},
              {"floor_heights", truth.floor_heights},         {"staircases", stairs}};
    if (truth.observer_floor_z) j["observer_floor_z"] = *truth.observer_floor_z;
    return j;
}

namespace {
SceneTruth parseGroundTruth(const json& j, const std::string& source) {
    if (!j.is_object() || !j.contains("format") || j["format"] != "stairmap-gt")
        fail(source, "not a stairmap ground-truth file (\"format\": \"stairmap-gt\" missing)");
    SceneTruth truth;
    if (j.contains("frame") && !j["frame"].is_string()) fail(source, "frame: must be a string");
    truth.frame = j.value("frame", "world");
    const json& floors = member(j, "floor_heights", source, "root");
    if (!floors.is_array()) fail(source, "floor_heights: must be an array");
    for (const auto& f : floors) {
        if (!f.is_number()) fail(source, "floor_heights: must hold numbers");
        truth.floor_heights.push_back(f.get<double>());
    }
    if (j.contains("observer_floor_z")) truth.observer_floor_z = number(j, "observer_floor_z", source, "root");
    const json& stairs = member(j, "staircases", source, "root");
    if (!stairs.is_array()) fail(source, "staircases: must be an array");
    for (std::size_t i = 0; i < stairs.size(); ++i)
        truth.staircases.push_back(staircaseFromJson(stairs[i], source, "staircases[" + std::to_string(i) + "]"));
    return truth;
}
}  // namespace

SceneTruth groundTruthFromJson(const json& j, const std::string& source) {
    try {
        return parseGroundTruth(j, source);
    } catch (const json::exception& e) {  // a value of the wrong type that no check above caught
        fail(source, std::string("wrong type of value: ") + e.what());
    }
}

void writeGroundTruthFile(const std::string& path, const SceneTruth& truth, const json& extra) {
    json j = groundTruthToJson(truth);
    for (auto it = extra.begin(); it != extra.end(); ++it) j[it.key()] = it.value();
    std::ofstream out(path);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    out << j.dump(1) << "\n";
    if (!out) throw std::runtime_error(path + ": write failed");
}

SceneTruth readGroundTruthFile(const std::string& path) {
    std::ifstream in = openInputFile(path, "a ground-truth (gt.json) file");
    json j;
    try {
        in >> j;
    } catch (const json::exception& e) {
        throw std::runtime_error(path + ": not valid JSON (" + e.what() + ")");
    }
    return groundTruthFromJson(j, path);
}

}  // namespace stairmap::io
