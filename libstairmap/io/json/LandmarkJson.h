#pragma once
// Persistence of the landmark map (issue 4, item 5): a versioned JSON document, schema in
// docs/landmarks.schema.json. Stream functions do the work; path helpers open files and delegate.
//
//   {"version":1, "frame":"world", "generator":"stairmap",
//    "floors":[{"id":i, "z":m, "robot_samples":n, "staircase_ends":n}],          (reported floors)
//    "staircases":[{"id":i, "confirmed":bool, "observations":n, "first_seen_s":s,
//       "last_seen_s":s, "bottom_observed":bool, "top_observed":bool, "bottom_floor":i, "top_floor":i, "direction":"ascending", "num_steps":k,
//       "step_height":m, "step_depth":m, "step_width":m, "slope_deg":deg, "location":[x,y,z],
//       "heading_deg":deg, "steps":[{"start":[x,y,z], "end":[x,y,z], "num_points":n,
//       "observations":n, "cov_rho_theta":[[c00,c01],[c10,c11]]}, ...]}],
//    "continuation":{ exact state to continue the map: next ids, all floor clusters with sums,
//       absorbed ids, exact radians }, "params":{ the LandmarkParams used }}
// Staircases are canonical (see map/LandmarkTypes.h): steps bottom to top, location = centre of
// the lowest edge, heading = uphill, world frame. Lengths [m], angles [deg] unless named _rad.

#include <iosfwd>
#include <stdexcept>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "map/LandmarkMap.h"
#include "map/LandmarkTypes.h"

namespace stairmap::io {

constexpr int kLandmarkJsonVersion = 1;

nlohmann::json landmarkStateToJson(const LandmarkMapState& state, const LandmarkParams& params);

/// Validating inverse. Throws std::runtime_error "<field>: <problem>" (e.g.
/// "staircases[1].steps[0].end: expected an array of 3 finite numbers", "version: unsupported 2").
/// `params_out`, if given, receives the params stored in the document.
LandmarkMapState landmarkStateFromJson(const nlohmann::json& json,
                                       LandmarkParams* params_out = nullptr);

/// Writes the document (pretty printed) to a stream. Throws std::runtime_error if the stream fails.
void writeLandmarkState(std::ostream& out, const LandmarkMapState& state,
                        const LandmarkParams& params);
/// Reads and validates a document; errors are prefixed with `source_name` ("<file>: <problem>").
LandmarkMapState readLandmarkState(std::istream& in, const std::string& source_name,
                                   LandmarkParams* params_out = nullptr);

/// Writes `path` atomically: a temp file in the same directory, flushed and fsync'ed, then
/// renamed over `path`. On any failure the previous file is left untouched, the temp file is
/// removed, and std::runtime_error names the path and the problem.
void saveLandmarkStateAtomic(const std::string& path, const LandmarkMapState& state,
                             const LandmarkParams& params);
/// Reads `path`; a missing, corrupt, truncated or wrong-version file throws std::runtime_error
/// "<path>: <problem>". Never modifies the file.
LandmarkMapState loadLandmarkState(const std::string& path, LandmarkParams* params_out = nullptr);

// Convenience wrappers on LandmarkMap (inline so that io/ does not link map/).
inline void saveLandmarkMapAtomic(const std::string& path, const LandmarkMap& map) {
    saveLandmarkStateAtomic(path, map.state(), map.params());
}
/// Builds a map from a loaded state; inconsistent content (e.g. duplicate ids) becomes
/// std::runtime_error "<path>: <problem>".
inline LandmarkMap landmarkMapFromState(const std::string& path, LandmarkMapState state,
                                        const LandmarkParams& params) {
    try {
        return LandmarkMap(std::move(state), params);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}
/// Continues a saved map with the given (current) parameters.
inline LandmarkMap loadLandmarkMap(const std::string& path, const LandmarkParams& params) {
    return landmarkMapFromState(path, loadLandmarkState(path), params);
}
/// Continues a saved map with the parameters stored in it.
inline LandmarkMap loadLandmarkMap(const std::string& path) {
    LandmarkParams stored;
    LandmarkMapState state = loadLandmarkState(path, &stored);
    return landmarkMapFromState(path, std::move(state), stored);
}

}  // namespace stairmap::io
