#include "export/FloorGraph.h"

#include <algorithm>
#include <limits>

namespace stairmap::exporting {
namespace {

/// Both ends of a flight as graph nodes (floor nodes, or new unknown ones).
struct FlightEnds {
    const GraphNode* bottom = nullptr;
    const GraphNode* top = nullptr;
};

class GraphBuilder {
  public:
    GraphBuilder(const std::map<int, FloorGrid>& grids, const std::vector<RobotProfile>& profiles,
                 const GraphParams& params)
        : grids_(grids), profiles_(profiles), params_(params) {}

    void addFloors(const std::vector<Floor>& floors, const std::vector<StaircaseLandmark>& stairs) {
        for (const Floor& f : floors) {
            GraphNode n;
            n.id = f.id;
            n.floor_id = f.id;
            n.z = f.z;
            n.extent = floorExtent(f, stairs);
            n.position = 0.5 * (n.extent.head<2>() + n.extent.tail<2>());
            graph_.nodes.push_back(n);
            next_id_ = std::max(next_id_, f.id + 1);
        }
    }

    void addStaircase(const StaircaseLandmark& s, const std::vector<Floor>& floors) {
        if (s.stairs.steps.empty()) return;
        const FlightGeometry g = flightBetweenFloors(s, floors);
        const int bottom = nodeFor(s.bottom_floor, g.bottom);
        const int top = nodeFor(s.top_floor, g.top);
        pending_.push_back({s, g, bottom, top});
    }

    FloorGraph finish() {
        // Edge ids follow every node id, so ids are unique across both.
        for (const Pending& p : pending_) {
            addEdge(p, Travel::Up);
            addEdge(p, Travel::Down);
        }
        return std::move(graph_);
    }

  private:
    struct Pending {
        const StaircaseLandmark& landmark;
        FlightGeometry flight;
        int bottom_node, top_node;
    };

    Eigen::Vector4d floorExtent(const Floor& f,
                                const std::vector<StaircaseLandmark>& stairs) const {
        const auto grid = grids_.find(f.id);
        if (grid != grids_.end()) {
            if (const auto e = freeExtent(grid->second)) return *e;
        }
        // No floor map: the staircase ends on this floor bound it.
        constexpr double kInf = std::numeric_limits<double>::infinity();
        Eigen::Vector4d e(kInf, kInf, -kInf, -kInf);
        for (const StaircaseLandmark& s : stairs) {
            if (s.stairs.steps.empty()) continue;
            const auto include = [&e](const StairEdge& edge) {
                e.head<2>() = e.head<2>().cwiseMin(edge.centre().head<2>());
                e.tail<2>() = e.tail<2>().cwiseMax(edge.centre().head<2>());
            };
            if (s.bottom_floor == f.id) include(s.stairs.steps.front());
            if (s.top_floor == f.id) include(s.stairs.steps.back());
        }
        return e.allFinite() ? e : Eigen::Vector4d::Zero();
    }

    int nodeFor(int floor_id, const Eigen::Vector3d& end) {
        for (const GraphNode& n : graph_.nodes) {
            if (n.known && n.floor_id == floor_id && floor_id >= 0) return n.id;
        }
        GraphNode n;
        n.id = next_id_++;
        n.known = false;
        n.z = end.z();
        n.position = end.head<2>();
        n.extent << end.x(), end.y(), end.x(), end.y();
        graph_.nodes.push_back(n);
        return n.id;
    }

    const GraphNode& node(int id) const {
        return *std::find_if(graph_.nodes.begin(), graph_.nodes.end(),
                             [id](const GraphNode& n) { return n.id == id; });
    }

    const FloorGrid* gridFor(const GraphNode& n) const {
        const auto it = grids_.find(n.floor_id);
        return n.known && it != grids_.end() ? &it->second : nullptr;
    }

    EdgeRobot judge(const Pending& p, Travel travel, const RobotProfile& robot) const {
        const GraphNode& bottom = node(p.bottom_node);
        const GraphNode& top = node(p.top_node);
        const Eigen::Vector2d up = headingVector(p.flight.heading_rad);
        const ApproachPose at_bottom = findApproach(gridFor(bottom), p.flight.bottom.head<2>(), -up,
                                                    bottom.z, robot, params_.approach);
        const ApproachPose at_top =
            findApproach(gridFor(top), p.flight.top.head<2>(), up, top.z, robot, params_.approach);
        EdgeRobot r;
        r.robot = robot.name;
        r.verdict = judgeFlight(p.flight, robot, travel);
        if (at_bottom.checked && !at_bottom.clear)
            r.verdict.refuse("no clear approach at the bottom");
        if (at_top.checked && !at_top.clear) r.verdict.refuse("no clear approach at the top");
        r.start = travel == Travel::Up ? at_bottom : at_top;
        r.goal = travel == Travel::Up ? at_top : at_bottom;
        return r;
    }

    void addEdge(const Pending& p, Travel travel) {
        GraphEdge e;
        e.id = next_id_++;
        e.staircase_id = p.landmark.id;
        e.travel = travel;
        e.from = travel == Travel::Up ? p.bottom_node : p.top_node;
        e.to = travel == Travel::Up ? p.top_node : p.bottom_node;
        e.flight = p.flight;
        e.length_m = p.flight.length_m;
        e.cost =
            e.length_m * (travel == Travel::Up ? params_.up_cost_factor : params_.down_cost_factor);
        for (const RobotProfile& robot : profiles_) e.robots.push_back(judge(p, travel, robot));
        e.confirmed = p.landmark.confirmed;
        e.observations = p.landmark.observations;
        e.first_seen_s = p.landmark.first_seen_s;
        e.last_seen_s = p.landmark.last_seen_s;
        graph_.edges.push_back(std::move(e));
    }

    const std::map<int, FloorGrid>& grids_;
    const std::vector<RobotProfile>& profiles_;
    GraphParams params_;
    FloorGraph graph_;
    std::vector<Pending> pending_;
    int next_id_ = 0;
};

}  // namespace

FlightGeometry flightBetweenFloors(const StaircaseLandmark& landmark,
                                   const std::vector<Floor>& floors) {
    FlightGeometry g = measureFlight(landmark);
    const auto heightOf = [&floors](int id) {
        for (const Floor& f : floors) {
            if (f.id == id && id >= 0) return f.z;
        }
        return std::numeric_limits<double>::quiet_NaN();
    };
    extendToFloors(g, heightOf(landmark.bottom_floor), heightOf(landmark.top_floor));
    return g;
}

FloorGraph buildFloorGraph(const std::vector<StaircaseLandmark>& staircases,
                           const std::vector<Floor>& floors, const std::map<int, FloorGrid>& grids,
                           const std::vector<RobotProfile>& profiles, const GraphParams& params) {
    GraphBuilder builder(grids, profiles, params);
    builder.addFloors(floors, staircases);
    for (const StaircaseLandmark& s : staircases) builder.addStaircase(s, floors);
    return builder.finish();
}

}  // namespace stairmap::exporting
