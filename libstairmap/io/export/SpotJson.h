#pragma once
// staircases_spot.json: {"frame_name", "generator", "staircases":[...]} where each element is a
// bosdyn.api.StaircaseWithLandings in protobuf's JSON mapping (proto field names; enums as
// strings), so google.protobuf.json_format.ParseDict(element, StaircaseWithLandings()) reads it.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "export/SpotStaircase.h"

namespace stairmap::io {

nlohmann::json spotStaircaseToJson(const exporting::SpotStaircase& staircase,
                                   const std::string& frame_name = "world");
nlohmann::json spotStaircasesToJson(const std::vector<exporting::SpotStaircase>& staircases,
                                    const std::string& frame_name = "world");

}  // namespace stairmap::io
