#pragma once
// The floor graph a planner searches: floors are nodes, each staircase two directed edges (up and
// down) with a verdict and approach poses per robot profile. A flight end on no known floor leads
// to an "unknown" node of its own, so a planner sees where the map stops.

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "export/ApproachPose.h"
#include "export/FlightGeometry.h"
#include "export/FloorGrid.h"
#include "export/RobotProfile.h"
#include "export/Traversability.h"
#include "map/LandmarkTypes.h"

namespace stairmap::exporting {

struct GraphNode {
    int id = -1;        ///< unique among nodes and edges (Nav2's route graph needs that)
    int floor_id = -1;  ///< landmarks.json floor id; -1 for an unknown node
    bool known = true;  ///< false: the end of a flight on no mapped floor
    double z = 0.0;     ///< [m] floor height (unknown node: the flight end's height)
    Eigen::Vector4d extent = Eigen::Vector4d::Zero();  ///< [m] min x, min y, max x, max y
    Eigen::Vector2d position =
        Eigen::Vector2d::Zero();  ///< [m] centre of the extent (a point for GeoJSON)
};

/// One robot's view of one directed edge.
struct EdgeRobot {
    std::string robot;
    Verdict verdict;
    ApproachPose start;  ///< where it stands before the flight (bottom going up, top going down)
    ApproachPose goal;   ///< where it arrives
};

struct GraphEdge {
    int id = -1;
    int staircase_id = -1;
    Travel travel = Travel::Up;
    int from = -1, to = -1;  ///< node ids
    double length_m = 0.0;  ///< [m] 3D length of the flight (foot of the first riser to top nosing)
    double cost = 0.0;      ///< length x the direction's cost factor
    FlightGeometry flight;
    std::vector<EdgeRobot> robots;  ///< in the order of the profiles
    // Knowledge from the landmark map.
    bool confirmed = false;
    int observations = 0;
    double first_seen_s = 0.0, last_seen_s = 0.0;
};

struct FloorGraph {
    std::vector<GraphNode> nodes;
    std::vector<GraphEdge> edges;
};

struct GraphParams {
    double up_cost_factor = 2.0;    ///< [-] cost per metre of flight going up (floor = 1)
    double down_cost_factor = 1.5;  ///< [-] cost per metre going down
    ApproachParams approach;
};

/// measureFlight + extendToFloors with the heights of the landmark's floors (those in `floors`).
FlightGeometry flightBetweenFloors(const StaircaseLandmark& landmark,
                                   const std::vector<Floor>& floors);

/// `grids` maps a floor id to its floor map (missing: approaches are not checked). A blocked
/// approach (checked and not clear) refuses the edge for that robot. Profiles must be valid.
FloorGraph buildFloorGraph(const std::vector<StaircaseLandmark>& staircases,
                           const std::vector<Floor>& floors, const std::map<int, FloorGrid>& grids,
                           const std::vector<RobotProfile>& profiles,
                           const GraphParams& params = {});

}  // namespace stairmap::exporting
