#pragma once
// LandmarkParams <-> JSON ({"landmarks":{key:value,...},"floors":{...}}), recorded in every map.

#include <string>

#include <nlohmann/json.hpp>

#include "map/LandmarkParams.h"

namespace stairmap::io {

nlohmann::json landmarkParamsToJson(const LandmarkParams& params);
/// Missing keys keep their defaults; wrong types or out-of-range values throw std::runtime_error
/// "<path>.<section>.<key>: <problem>".
LandmarkParams landmarkParamsFromJson(const nlohmann::json& json, const std::string& path);

}  // namespace stairmap::io
