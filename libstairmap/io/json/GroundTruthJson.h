#pragma once
// gt.json: the ground truth of a simulated scene (schema in docs/simulator.md).

#include <nlohmann/json.hpp>
#include <string>

#include "core/GroundTruth.h"

namespace stairmap::io {

/// JSON object with "format": "stairmap-gt", "version": 1, "frame", "floor_heights",
/// optional "observer_floor_z", and "staircases" (nosings bottom to top).
nlohmann::json groundTruthToJson(const SceneTruth& truth);

/// Parses what groundTruthToJson writes (extra keys are ignored). Throws std::runtime_error
/// naming `source` and the offending key on a malformed document.
SceneTruth groundTruthFromJson(const nlohmann::json& json, const std::string& source);

/// File wrappers. `extra` keys are merged into the top-level object (e.g. scene name, pose).
void writeGroundTruthFile(const std::string& path, const SceneTruth& truth,
                          const nlohmann::json& extra = nlohmann::json::object());
SceneTruth readGroundTruthFile(const std::string& path);

}  // namespace stairmap::io
