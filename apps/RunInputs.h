#pragma once
// What `map` and `live` read before a run: the mapper's parameters and the landmark map to continue.
// `input` names the file being read, for errors that cannot name it themselves (Commands.h).

#include <string>

#include "io/config/MapperConfig.h"
#include "io/json/LandmarkJson.h"
#include "pipeline/MapperParams.h"

namespace stairmap::apps {

/// --config, or the built-in defaults when none is given.
inline pipeline::MapperParams loadRunParams(const std::string& config, std::string& input) {
    input = config;
    return config.empty() ? pipeline::MapperParams{} : io::loadMapperParams(config);
}

/// --map-in, or an empty map when none is given.
inline LandmarkMap loadRunLandmarks(const std::string& map_in, const LandmarkParams& params,
                                    std::string& input) {
    if (map_in.empty()) return LandmarkMap(params);
    input = map_in;
    return io::loadLandmarkMap(map_in, params);
}

}  // namespace stairmap::apps
