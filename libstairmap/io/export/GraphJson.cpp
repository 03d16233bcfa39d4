#include "io/export/GraphJson.h"

#include <cmath>

namespace stairmap::io {
namespace {

using exporting::ApproachPose;
using exporting::FloorGraph;
using exporting::GraphEdge;
using exporting::GraphNode;

double deg(double rad) { return rad * 180.0 / M_PI; }

nlohmann::json xyz(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

nlohmann::json extentJson(const Eigen::Vector4d& e) {
    return {{"min_x", e[0]}, {"min_y", e[1]}, {"max_x", e[2]}, {"max_y", e[3]}};
}

nlohmann::json poseJson(const ApproachPose& p) {
    return {{"x", p.position.x()},
            {"y", p.position.y()},
            {"z", p.position.z()},
            {"yaw_deg", deg(p.yaw_rad)},
            {"checked", p.checked},
            {"clear", p.clear},
            {"on_seen_floor", p.on_seen_floor}};
}

nlohmann::json nodeJson(const GraphNode& n) {
    return {{"id", n.id},
            {"kind", n.known ? "floor" : "unknown"},
            {"floor_id", n.floor_id},
            {"z", n.z},
            {"position", {n.position.x(), n.position.y(), n.z}},
            {"extent", extentJson(n.extent)}};
}

nlohmann::json landingsJson(const exporting::FlightGeometry& f) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& l : f.mid_landings) {
        out.push_back(
            {{"centre", xyz(l.centre)}, {"length_m", l.length_m}, {"width_m", l.width_m}});
    }
    return out;
}

nlohmann::json geometryJson(const exporting::FlightGeometry& f) {
    return {{"rise_m", f.rise_m},
            {"run_m", f.run_m},
            {"width_m", f.width_m},
            {"slope_deg", f.slope_deg},
            {"risers", f.risers},
            {"observed_risers", f.observed_risers},
            {"inferred_risers_bottom", f.inferred_risers_bottom},
            {"inferred_risers_top", f.inferred_risers_top},
            {"max_risers_between_landings", f.max_risers_between_landings},
            {"heading_deg", deg(f.heading_rad)},
            {"bottom", xyz(f.bottom)},
            {"top", xyz(f.top)},
            {"uncertainty",
             {{"rise_std_m", f.rise_std_m},
              {"run_std_m", f.run_std_m},
              {"width_std_m", f.width_std_m}}}};
}

nlohmann::json edgeJson(const GraphEdge& e) {
    nlohmann::json robots = nlohmann::json::object();
    for (const auto& r : e.robots) {
        robots[r.robot] = {{"traversable", r.verdict.traversable},
                           {"reasons", r.verdict.reasons},
                           {"start", poseJson(r.start)},
                           {"goal", poseJson(r.goal)}};
    }
    return {{"id", e.id},
            {"staircase_id", e.staircase_id},
            {"direction", exporting::travelName(e.travel)},
            {"from", e.from},
            {"to", e.to},
            {"length_m", e.length_m},
            {"cost", e.cost},
            {"geometry", geometryJson(e.flight)},
            {"landings", landingsJson(e.flight)},
            {"robots", robots},
            {"knowledge",
             {{"confirmed", e.confirmed},
              {"observations", e.observations},
              {"first_seen_s", e.first_seen_s},
              {"last_seen_s", e.last_seen_s}}}};
}

}  // namespace

nlohmann::json robotProfileToJson(const exporting::RobotProfile& p) {
    return {{"name", p.name},
            {"max_rise_m", p.max_rise_m},
            {"min_run_m", p.min_run_m},
            {"min_width_m", p.min_width_m},
            {"max_slope_deg", p.max_slope_deg},
            {"max_steps_without_landing", p.max_steps_without_landing},
            {"can_ascend", p.can_ascend},
            {"can_descend", p.can_descend},
            {"footprint_length_m", p.footprint_length_m},
            {"footprint_width_m", p.footprint_width_m},
            {"clearance_m", p.clearance_m},
            {"height_m", p.height_m}};
}

nlohmann::json graphToJson(const FloorGraph& graph,
                           const std::vector<exporting::RobotProfile>& profiles,
                           const std::string& source) {
    nlohmann::json j = {{"version", kGraphJsonVersion},
                        {"frame", "world"},
                        {"generator", "stairmap export"},
                        {"source", source}};
    j["robots"] = nlohmann::json::array();
    for (const auto& p : profiles) j["robots"].push_back(robotProfileToJson(p));
    j["nodes"] = nlohmann::json::array();
    for (const auto& n : graph.nodes) j["nodes"].push_back(nodeJson(n));
    j["edges"] = nlohmann::json::array();
    for (const auto& e : graph.edges) j["edges"].push_back(edgeJson(e));
    return j;
}

}  // namespace stairmap::io
