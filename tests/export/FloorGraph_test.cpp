// Floor graphs from synthetic landmark maps with known stairs: nodes, edges, verdicts, approaches.
#include "export/FloorGraph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "SyntheticLandmarks.h"

namespace stairmap::exporting {
namespace {

/// Stair 3: floor 0 -> 1 along +x, 16 x 0.1875 m from (2, 1, 0) to the top nosing at (6.2, 1, 3).
/// Stair 7: from floor 0 along +y at (10, 5), 10 x 0.17 m; its top floor is unknown.
struct TwoFloorMap {
    std::vector<StaircaseLandmark> stairs;
    std::vector<Floor> floors = {test::makeFloor(0, 0.0), test::makeFloor(1, 3.0)};
    test::FlightSpec a, b;

    TwoFloorMap() {
        a.foot = {2.0, 1.0, 0.0};
        a.rise = 0.1875;
        a.risers = 16;
        a.width = 1.2;
        b.foot = {10.0, 5.0, 0.0};
        b.heading_rad = M_PI / 2;
        stairs = {test::makeLandmark(3, a, 0, 1), test::makeLandmark(7, b, 0, -1)};
    }
};

RobotProfile robot(double max_rise) {
    RobotProfile p;
    p.name = "r" + std::to_string(max_rise);
    p.max_rise_m = max_rise;
    p.max_slope_deg = 40.0;
    return p;
}

const GraphEdge& edgeOf(const FloorGraph& g, int staircase, Travel t) {
    for (const GraphEdge& e : g.edges) {
        if (e.staircase_id == staircase && e.travel == t) return e;
    }
    throw std::runtime_error("edge not found");
}

TEST(FloorGraph, NodesAndEdgesOfKnownStairs) {
    const TwoFloorMap m;
    const FloorGraph g = buildFloorGraph(m.stairs, m.floors, {}, {robot(0.18)});
    ASSERT_EQ(g.nodes.size(), 3u);  // two floors + the unknown top of stair 7
    EXPECT_EQ(g.nodes[0].floor_id, 0);
    EXPECT_EQ(g.nodes[1].floor_id, 1);
    const GraphNode& unknown = g.nodes[2];
    EXPECT_FALSE(unknown.known);
    EXPECT_EQ(unknown.floor_id, -1);
    EXPECT_NEAR(unknown.z, 10 * 0.17, 1e-9);
    EXPECT_NEAR(unknown.position.x(), 10.0, 1e-9);
    EXPECT_NEAR(unknown.position.y(), 5.0 + 9 * 0.28, 1e-9);

    ASSERT_EQ(g.edges.size(), 4u);
    EXPECT_EQ(edgeOf(g, 3, Travel::Up).from, 0);
    EXPECT_EQ(edgeOf(g, 3, Travel::Up).to, 1);
    EXPECT_EQ(edgeOf(g, 3, Travel::Down).from, 1);
    EXPECT_EQ(edgeOf(g, 3, Travel::Down).to, 0);
    EXPECT_EQ(edgeOf(g, 7, Travel::Up).to, unknown.id);
    EXPECT_EQ(edgeOf(g, 7, Travel::Down).from, unknown.id);

    std::set<int> ids;
    for (const auto& n : g.nodes) ids.insert(n.id);
    for (const auto& e : g.edges) ids.insert(e.id);
    EXPECT_EQ(ids.size(), g.nodes.size() + g.edges.size()) << "ids must be unique across both";

    const GraphEdge& up = edgeOf(g, 3, Travel::Up);
    EXPECT_NEAR(up.length_m, 0.1875 + 15 * std::hypot(0.1875, 0.28), 1e-9);
    EXPECT_GT(up.cost, edgeOf(g, 3, Travel::Down).cost);  // climbing costs more
    EXPECT_TRUE(up.confirmed);
    EXPECT_EQ(up.observations, 5);
    EXPECT_DOUBLE_EQ(up.last_seen_s, 42.0);
}

TEST(FloorGraph, VerdictsPerRobotBothWays) {
    const TwoFloorMap m;
    const FloorGraph g = buildFloorGraph(m.stairs, m.floors, {}, {robot(0.18), robot(0.19)});
    for (Travel t : {Travel::Up, Travel::Down}) {
        const GraphEdge& a = edgeOf(g, 3, t);
        ASSERT_EQ(a.robots.size(), 2u);
        EXPECT_FALSE(a.robots[0].verdict.traversable);  // 0.1875 > 0.18
        EXPECT_EQ(a.robots[0].verdict.reasons, std::vector<std::string>{"rise 0.188 > 0.180 m"});
        EXPECT_TRUE(a.robots[1].verdict.traversable);
        EXPECT_TRUE(edgeOf(g, 7, t).robots[0].verdict.traversable);  // 0.17 m rises
        EXPECT_FALSE(a.robots[0].start.checked);                     // no floor maps given
    }
}

TEST(FloorGraph, FlightSeenInPartIsContinuedToItsFloors) {
    // Only the lowest 6 of stair 3's 16 nosings were seen; the landmark still joins floors 0 and 1.
    TwoFloorMap m;
    m.stairs[0].stairs.steps.resize(6);
    const FloorGraph g = buildFloorGraph(m.stairs, m.floors, {}, {robot(0.19)});
    const FlightGeometry& f = edgeOf(g, 3, Travel::Up).flight;
    EXPECT_EQ(f.observed_risers, 6);
    EXPECT_EQ(f.inferred_risers_top, 10);
    EXPECT_EQ(f.inferred_risers_bottom, 0);
    EXPECT_EQ(f.risers, 16);
    EXPECT_EQ(f.max_risers_between_landings, 16);
    EXPECT_LT((f.top - Eigen::Vector3d(6.2, 1.0, 3.0)).norm(), 1e-9);  // the true top nosing
    EXPECT_NEAR(edgeOf(g, 3, Travel::Up).length_m, 0.1875 + 15 * std::hypot(0.1875, 0.28), 1e-9);
    // Seen from the top only (the 5 highest nosings): continued down to floor 0.
    TwoFloorMap top;
    top.stairs[0].stairs.steps.erase(top.stairs[0].stairs.steps.begin(),
                                     top.stairs[0].stairs.steps.begin() + 11);
    const FloorGraph g2 = buildFloorGraph(top.stairs, top.floors, {}, {robot(0.19)});
    const FlightGeometry& f2 = edgeOf(g2, 3, Travel::Down).flight;
    EXPECT_EQ(f2.inferred_risers_bottom, 11);
    EXPECT_LT((f2.bottom - Eigen::Vector3d(2.0, 1.0, 0.0)).norm(), 1e-9);
}

/// Floor maps: floor 0 seen over [-3, 13] x [-2, 12], floor 1 over [6.2, 12] x [-1, 4].
std::map<int, FloorGrid> floorMaps(const PointCloud& extra = {}) {
    PointCloud c = extra;
    test::addFloorVoxels(c, -3.0, 13.0, -2.0, 12.0, 0.0);
    test::addFloorVoxels(c, 6.2, 12.0, -1.0, 4.0, 3.0);
    FloorRasterParams p;
    return {{0, rasteriseFloor(c, 0.0, p)}, {1, rasteriseFloor(c, 3.0, p)}};
}

bool onFreeCell(const FloorGrid& g, const Eigen::Vector3d& p) {
    const auto c = g.cellOf(p.x(), p.y());
    return c && g.at(c->first, c->second) == Cell::Free;
}

TEST(FloorGraph, ApproachPosesOnFreeFloorFacingTheFlight) {
    const TwoFloorMap m;
    const auto grids = floorMaps();
    RobotProfile r = robot(0.19);
    const FloorGraph g = buildFloorGraph(m.stairs, m.floors, grids, {r});
    const EdgeRobot& up = edgeOf(g, 3, Travel::Up).robots[0];
    const EdgeRobot& down = edgeOf(g, 3, Travel::Down).robots[0];
    EXPECT_TRUE(up.verdict.traversable) << ::testing::PrintToString(up.verdict.reasons);
    for (const ApproachPose* p : {&up.start, &up.goal}) {
        EXPECT_TRUE(p->checked && p->clear && p->on_seen_floor);
    }
    // Going up: start below the foot at x < 2 on floor 0 facing +x; goal beyond 6.2 on floor 1
    // facing back down (-x). Going down: the same two poses swapped.
    const double off = 0.5 * r.footprint_length_m + r.clearance_m;
    EXPECT_LT(up.start.position.x(), 2.0 - off);
    EXPECT_NEAR(up.start.position.y(), 1.0, 1e-9);
    EXPECT_NEAR(up.start.position.z(), 0.0, 1e-9);
    EXPECT_NEAR(std::cos(up.start.yaw_rad), 1.0, 1e-9);
    EXPECT_GT(up.goal.position.x(), 6.2 + off);
    EXPECT_NEAR(up.goal.position.z(), 3.0, 1e-9);
    EXPECT_NEAR(std::cos(up.goal.yaw_rad), -1.0, 1e-9);
    EXPECT_TRUE(onFreeCell(grids.at(0), up.start.position));
    EXPECT_TRUE(onFreeCell(grids.at(1), up.goal.position));
    EXPECT_LT((down.start.position - up.goal.position).norm(), 1e-9);
    EXPECT_LT((down.goal.position - up.start.position).norm(), 1e-9);
}

TEST(FloorGraph, ApproachBacksOffAnObstacleOrRefuses) {
    const TwoFloorMap m;
    RobotProfile r = robot(0.19);
    // A crate just in front of the first riser: the start moves back beyond it.
    PointCloud crate;
    test::addBoxVoxels(crate, {1.0, 0.5, 0.0}, {1.6, 1.5, 0.6});
    FloorGraph g = buildFloorGraph(m.stairs, m.floors, floorMaps(crate), {r});
    const EdgeRobot& up = edgeOf(g, 3, Travel::Up).robots[0];
    EXPECT_TRUE(up.start.clear);
    EXPECT_TRUE(up.verdict.traversable);
    // Its footprint + clearance ends before the crate's first cell centre (x = 1.025).
    EXPECT_LT(up.start.position.x() + 0.5 * r.footprint_length_m + r.clearance_m, 1.025);
    // A wall across the whole approach corridor: no clear pose, the edge is refused.
    PointCloud wall;
    test::addBoxVoxels(wall, {-3.0, 0.0, 0.0}, {1.9, 2.0, 1.0});
    g = buildFloorGraph(m.stairs, m.floors, floorMaps(wall), {r});
    const EdgeRobot& blocked = edgeOf(g, 3, Travel::Up).robots[0];
    EXPECT_FALSE(blocked.start.clear);
    EXPECT_FALSE(blocked.verdict.traversable);
    EXPECT_EQ(blocked.verdict.reasons, std::vector<std::string>{"no clear approach at the bottom"});
}

}  // namespace
}  // namespace stairmap::exporting
