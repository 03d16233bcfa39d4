#pragma once
// graph.json (schema docs/graph.schema.json) and graph.geojson (Nav2 Route Server layout) from a
// floor graph. World frame, metres, yaw in degrees unless a field is named _rad.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "export/FloorGraph.h"
#include "export/RobotProfile.h"

namespace stairmap::io {

constexpr int kGraphJsonVersion = 1;

/// The document: {"version", "frame", "generator", "source", "robots":[profiles], "nodes",
/// "edges"}. `source` names the map directory it was made from.
nlohmann::json graphToJson(const exporting::FloorGraph& graph,
                           const std::vector<exporting::RobotProfile>& profiles,
                           const std::string& source);

/// A GeoJSON FeatureCollection as nav2_route's GeoJsonGraphFileLoader reads it: nodes are Point
/// features with properties {id, frame, metadata}, edges MultiLineString features with {id,
/// startid, endid, cost, overridable, metadata}; ids unique across both; metadata holds only
/// numbers, booleans, strings, arrays of those and objects (what that loader accepts).
/// Coordinates carry z as a third value (GeoJSON altitude; Nav2 reads x and y).
nlohmann::json graphToGeoJson(const exporting::FloorGraph& graph, const std::string& frame = "map");

nlohmann::json robotProfileToJson(const exporting::RobotProfile& profile);

}  // namespace stairmap::io
