#include "io/json/LandmarkParamsJson.h"

#include <stdexcept>
#include <type_traits>

#include "io/json/JsonFields.h"
#include "map/LandmarkParamsFields.h"

namespace stairmap::io {

nlohmann::json landmarkParamsToJson(const LandmarkParams& params) {
    nlohmann::json out = nlohmann::json::object();
    map::forEachLandmarkParam(params, [&](const char* section, const char* key, const auto& value) {
        out[section][key] = value;
    });
    return out;
}

LandmarkParams landmarkParamsFromJson(const nlohmann::json& json, const std::string& path) {
    if (!json.is_object()) throw std::runtime_error(path + ": expected an object");
    LandmarkParams p;
    map::forEachLandmarkParam(p, [&](const char* section, const char* key, auto& value) {
        const auto sec = json.find(section);
        if (sec == json.end() || !sec->is_object() || !sec->contains(key)) return;
        const std::string where = path + "." + section + "." + key;
        const nlohmann::json& v = (*sec)[key];
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<T, bool>) {
            value = json_fields::boolean(v, where);
        } else if constexpr (std::is_same_v<T, int>) {
            value = json_fields::integer(v, where);
        } else {
            value = json_fields::finiteNumber(v, where);
        }
    });
    try {
        validateLandmarkParams(p);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
    return p;
}

}  // namespace stairmap::io
