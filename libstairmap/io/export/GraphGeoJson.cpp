// graph.geojson: the floor graph in the layout of nav2_route's GeoJSON graph files.
#include <cmath>

#include "io/export/GraphJson.h"

namespace stairmap::io {
namespace {

using exporting::FloorGraph;
using exporting::GraphEdge;
using exporting::GraphNode;

nlohmann::json point(const Eigen::Vector2d& xy, double z) { return {xy.x(), xy.y(), z}; }

const GraphNode& nodeById(const FloorGraph& g, int id) {
    for (const GraphNode& n : g.nodes) {
        if (n.id == id) return n;
    }
    return g.nodes.front();  // unreachable: edges only name nodes of the graph
}

nlohmann::json nodeFeature(const GraphNode& n, const std::string& frame) {
    nlohmann::json metadata = {{"kind", n.known ? "floor" : "unknown"},
                               {"floor_id", n.floor_id},
                               {"z", n.z},
                               {"min_x", n.extent[0]},
                               {"min_y", n.extent[1]},
                               {"max_x", n.extent[2]},
                               {"max_y", n.extent[3]}};
    return {{"type", "Feature"},
            {"properties", {{"id", n.id}, {"frame", frame}, {"metadata", metadata}}},
            {"geometry", {{"type", "Point"}, {"coordinates", point(n.position, n.z)}}}};
}

/// The path of the edge: start node, the flight's two ends in travel order, end node.
nlohmann::json edgeLine(const FloorGraph& g, const GraphEdge& e) {
    const GraphNode& from = nodeById(g, e.from);
    const GraphNode& to = nodeById(g, e.to);
    const bool up = e.travel == exporting::Travel::Up;
    const Eigen::Vector3d a = up ? e.flight.bottom : e.flight.top;
    const Eigen::Vector3d b = up ? e.flight.top : e.flight.bottom;
    return nlohmann::json::array(
        {nlohmann::json::array({point(from.position, from.z), point(a.head<2>(), a.z()),
                                point(b.head<2>(), b.z()), point(to.position, to.z)})});
}

nlohmann::json edgeMetadata(const GraphEdge& e) {
    nlohmann::json robots = nlohmann::json::object();
    nlohmann::json traversable_by = nlohmann::json::array();
    for (const auto& r : e.robots) {
        robots[r.robot] = {{"traversable", r.verdict.traversable},
                           {"reasons", r.verdict.reasons},
                           {"start_x", r.start.position.x()},
                           {"start_y", r.start.position.y()},
                           {"start_yaw_deg", r.start.yaw_rad * 180.0 / M_PI},
                           {"goal_x", r.goal.position.x()},
                           {"goal_y", r.goal.position.y()},
                           {"goal_yaw_deg", r.goal.yaw_rad * 180.0 / M_PI}};
        if (r.verdict.traversable) traversable_by.push_back(r.robot);
    }
    return {{"kind", "stairs"},
            {"staircase_id", e.staircase_id},
            {"direction", exporting::travelName(e.travel)},
            {"length_m", e.length_m},
            {"rise_m", e.flight.rise_m},
            {"run_m", e.flight.run_m},
            {"width_m", e.flight.width_m},
            {"slope_deg", e.flight.slope_deg},
            {"risers", e.flight.risers},
            {"confirmed", e.confirmed},
            {"observations", e.observations},
            {"traversable_by", traversable_by},
            {"robots", robots}};
}

}  // namespace

nlohmann::json graphToGeoJson(const FloorGraph& graph, const std::string& frame) {
    nlohmann::json features = nlohmann::json::array();
    for (const GraphNode& n : graph.nodes) features.push_back(nodeFeature(n, frame));
    for (const GraphEdge& e : graph.edges) {
        features.push_back(
            {{"type", "Feature"},
             {"properties",
              {{"id", e.id},
               {"startid", e.from},
               {"endid", e.to},
               {"cost", e.cost},
               {"overridable", true},
               {"metadata", edgeMetadata(e)}}},
             {"geometry", {{"type", "MultiLineString"}, {"coordinates", edgeLine(graph, e)}}}});
    }
    return {
        {"type", "FeatureCollection"}, {"name", "stairmap_floor_graph"}, {"features", features}};
}

}  // namespace stairmap::io
