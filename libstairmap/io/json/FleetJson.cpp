#include "io/json/FleetJson.h"

#include <cmath>
#include <stdexcept>

#include "io/json/JsonFields.h"
#include "io/system/AtomicFile.h"

namespace stairmap::io {
namespace {

using nlohmann::json;
namespace jf = json_fields;
constexpr double kRadToDeg = 180.0 / M_PI;

json recordToJson(const AlignmentRecord& r) {
    json pairs = json::array();
    for (const fleet::LandmarkPair& p : r.pairs) pairs.push_back({p.first_id, p.other_id});
    return {{"source", r.source},
            {"T_first_this",
             {{"x", r.T_first_this.x},
              {"y", r.T_first_this.y},
              {"z", r.T_first_this.z},
              {"yaw_deg", r.T_first_this.yaw_rad * kRadToDeg}}},
            {"sigma",
             {{"xy_m", r.sigma.xy_m}, {"z_m", r.sigma.z_m}, {"yaw_deg", r.sigma.yaw_deg}}},
            {"pairs", pairs}};
}

double number(const json& object, const char* key, const std::string& path) {
    return jf::finiteNumber(jf::member(object, key, path), path + "." + key);
}

AlignmentRecord recordFromJson(const json& j, const std::string& path) {
    AlignmentRecord r;
    r.source = jf::text(jf::member(j, "source", path), path + ".source");
    const std::string tp = path + ".T_first_this";
    const json& T = jf::member(j, "T_first_this", path);
    r.T_first_this = {number(T, "x", tp), number(T, "y", tp), number(T, "z", tp),
                      number(T, "yaw_deg", tp) / kRadToDeg};
    const std::string sp = path + ".sigma";
    const json& s = jf::member(j, "sigma", path);
    r.sigma = {number(s, "xy_m", sp), number(s, "z_m", sp), number(s, "yaw_deg", sp)};
    const json& pairs = jf::arrayMember(j, "pairs", path);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const std::string pp = path + ".pairs[" + std::to_string(i) + "]";
        if (!pairs[i].is_array() || pairs[i].size() != 2)
            throw std::runtime_error(pp + ": expected [ID_in_first, ID_in_this]");
        r.pairs.push_back({jf::integer(pairs[i][0], pp + "[0]"), jf::integer(pairs[i][1], pp + "[1]")});
    }
    return r;
}

}  // namespace

json alignmentToJson(const std::vector<AlignmentRecord>& maps) {
    json entries = json::array();
    for (const AlignmentRecord& r : maps) entries.push_back(recordToJson(r));
    return {{"maps", entries}};
}

std::vector<AlignmentRecord> alignmentFromJson(const json& doc) {
    const json& maps = jf::arrayMember(doc, "maps", "");
    std::vector<AlignmentRecord> out;
    for (std::size_t i = 0; i < maps.size(); ++i)
        out.push_back(recordFromJson(maps[i], "maps[" + std::to_string(i) + "]"));
    return out;
}

json provenanceToJson(const std::vector<fleet::LandmarkProvenance>& provenance,
                      const std::vector<std::string>& sources) {
    json staircases = json::array();
    for (const fleet::LandmarkProvenance& p : provenance) {
        json srcs = json::array(), steps = json::array();
        for (const fleet::Contribution& c : p.sources)
            srcs.push_back({{"map", c.map}, {"id", c.source_id}, {"observations", c.observations}});
        for (const auto& step : p.steps) {
            json entry = json::array();
            for (const fleet::Contribution& c : step)
                entry.push_back({{"map", c.map}, {"observations", c.observations}});
            steps.push_back(entry);
        }
        staircases.push_back({{"id", p.id}, {"sources", srcs}, {"steps", steps}});
    }
    return {{"maps", sources}, {"staircases", staircases}};
}

void saveAlignment(const std::string& path, const std::vector<AlignmentRecord>& maps) {
    writeTextFileAtomic(path, alignmentToJson(maps).dump(2) + "\n");
}

void saveProvenance(const std::string& path,
                    const std::vector<fleet::LandmarkProvenance>& provenance,
                    const std::vector<std::string>& sources) {
    writeTextFileAtomic(path, provenanceToJson(provenance, sources).dump(2) + "\n");
}

}  // namespace stairmap::io
