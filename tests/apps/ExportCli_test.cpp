// `stairmap export` end to end on the bundled two-floor run, and its bad-input exits.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include "CliRunner.h"
#include "export/RobotProfile.h"
#include "io/config/RobotProfileConfig.h"
#include "io/export/MapServerReader.h"
#include "io/rawlog/TumTrajectory.h"

namespace stairmap::test {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

const std::string kSrc = STAIRMAP_SOURCE_DIR;
const std::vector<std::string> kPresets = {"tracked", "quadruped", "scout"};

std::string presetPath(const std::string& name) { return kSrc + "/config/robots/" + name + ".ini"; }

std::string robotArgs() {
    std::string args;
    for (const auto& p : kPresets) args += " --robot '" + presetPath(p) + "'";
    return args;
}

json readJsonFile(const std::string& path) {
    std::ifstream in(path);
    return json::parse(in);
}

/// A world point of the two-floor run carried into the frame of the poses handed to the mapper
/// (poses.tum, with drift) by the error of the true pose nearest to it (gt_trajectory.tum).
Eigen::Vector3d intoEstimatedFrame(const Eigen::Vector3d& world) {
    const std::string ds = kSrc + "/datasets/two_floor/";
    const auto est = io::TumTrajectory::load(ds + "poses.tum").poses();
    const auto truth = io::TumTrajectory::load(ds + "gt_trajectory.tum").poses();
    EXPECT_EQ(est.size(), truth.size());
    const auto distance = [&](std::size_t i) {
        return (truth[i].T_world_robot.translation() - world).head<2>().norm();
    };
    std::size_t k = 0;
    for (std::size_t i = 0; i < std::min(est.size(), truth.size()); ++i)
        if (distance(i) < distance(k)) k = i;
    return est[k].T_world_robot * (truth[k].T_world_robot.inverse() * world);
}

class ExportTwoFloor : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        dir_ = cliScratchDir("export", "two_floor." + std::to_string(::getpid()));
        const std::string ds = kSrc + "/datasets/two_floor/";
        const CliResult map = runStairmap(
            "map '" + ds + "two_floor.rawlog' --poses '" + ds + "poses.tum' --config '" + kSrc +
                "/config/sim_legged_vlp16.ini' --out '" + dir_ + "/map' --quiet",
            dir_);
        ASSERT_EQ(map.exit_code, 0) << map.err;
        result_ = runStairmap(
            "export '" + dir_ + "/map'" + robotArgs() + " --out '" + dir_ + "/export'", dir_);
        ASSERT_EQ(result_.exit_code, 0) << result_.err;
        graph_ = readJsonFile(dir_ + "/export/graph.json");
        gt_ = readJsonFile(ds + "gt.json");
    }
    static std::string out(const std::string& name) { return dir_ + "/export/" + name; }

    static inline std::string dir_;
    static inline CliResult result_;
    static inline json graph_, gt_;
};

const json& nodeById(const json& graph, int id) {
    for (const json& n : graph.at("nodes")) {
        if (n.at("id") == id) return n;
    }
    throw std::runtime_error("no node " + std::to_string(id));
}

TEST_F(ExportTwoFloor, TwoFloorsJoinedByTwoFlightsBothWays) {
    const json& nodes = graph_.at("nodes");
    ASSERT_EQ(nodes.size(), 2u) << graph_.dump(1);
    const double z0 = gt_.at("floor_heights").at(0), z1 = gt_.at("floor_heights").at(1);
    EXPECT_NEAR(nodes.at(0).at("z").get<double>(), z0, 0.1);
    EXPECT_NEAR(nodes.at(1).at("z").get<double>(), z1, 0.1);
    for (const json& n : nodes) EXPECT_EQ(n.at("kind"), "floor");
    const json& edges = graph_.at("edges");
    ASSERT_EQ(edges.size(), 4u);
    std::map<int, std::set<std::string>> directions;
    for (const json& e : edges) {
        directions[e.at("staircase_id")].insert(e.at("direction").get<std::string>());
        const double from_z = nodeById(graph_, e.at("from")).at("z");
        const double to_z = nodeById(graph_, e.at("to")).at("z");
        if (e.at("direction") == "up") {
            EXPECT_NEAR(from_z, z0, 0.1);
            EXPECT_NEAR(to_z, z1, 0.1);
        } else {
            EXPECT_NEAR(from_z, z1, 0.1);
            EXPECT_NEAR(to_z, z0, 0.1);
        }
    }
    ASSERT_EQ(directions.size(), 2u);
    for (const auto& [id, d] : directions)
        EXPECT_EQ(d, (std::set<std::string>{"up", "down"})) << id;
}

/// The verdict the ground-truth geometry implies for a profile (limits inclusive).
bool impliedVerdict(const exporting::RobotProfile& p, const json& stair, bool up) {
    const double rise = stair.at("rise_m"), run = stair.at("run_m"), width = stair.at("width_m");
    const double slope = std::atan2(rise, run) * 180.0 / M_PI;
    const int risers = stair.at("num_risers");
    return (up ? p.can_ascend : p.can_descend) && rise <= p.max_rise_m && run >= p.min_run_m &&
           width >= p.min_width_m && slope <= p.max_slope_deg &&
           risers <= p.max_steps_without_landing;
}

TEST_F(ExportTwoFloor, VerdictsThePresetsImply) {
    for (const std::string& name : kPresets) {
        const auto profile = io::loadRobotProfile(presetPath(name));
        for (const json& e : graph_.at("edges")) {
            const bool up = e.at("direction") == "up";
            // Both bundled flights share one geometry (gt.json); each preset is far from its
            // limits.
            const bool expected = impliedVerdict(profile, gt_.at("staircases").at(0), up);
            const json& r = e.at("robots").at(name);
            EXPECT_EQ(r.at("traversable").get<bool>(), expected)
                << name << " edge " << e.at("id") << ": " << r.dump();
            if (!expected) continue;
            // Approach poses: checked in the voxel map, clear, on seen floor, facing the flight.
            const double heading = e.at("geometry").at("heading_deg").get<double>() * M_PI / 180.0;
            for (const char* which : {"start", "goal"}) {
                const json& pose = r.at(which);
                EXPECT_TRUE(pose.at("checked") && pose.at("clear") && pose.at("on_seen_floor"))
                    << name << " " << which << ": " << pose.dump();
                const bool at_bottom = up == (std::string(which) == "start");
                const double yaw = pose.at("yaw_deg").get<double>() * M_PI / 180.0;
                EXPECT_NEAR(std::cos(yaw - heading), at_bottom ? 1.0 : -1.0, 1e-6) << pose.dump();
            }
        }
    }
    EXPECT_EQ(graph_.at("edges").at(0).at("robots").at("scout").at("reasons").at(0),
              "cannot climb stairs up");
}

TEST_F(ExportTwoFloor, FloorMapsAndStairMasksReadBack) {
    for (const json& n : graph_.at("nodes")) {
        const std::string stem = "floor_" + std::to_string(n.at("floor_id").get<int>());
        const MapServerMap floor = readMapServerMap(out(stem + ".yaml"));
        const MapServerMap mask = readMapServerMap(out(stem + "_stairs.yaml"));
        EXPECT_DOUBLE_EQ(floor.resolution, 0.05);  // [map] resolution_m of the mapping config
        EXPECT_EQ(mask.width, floor.width);
        EXPECT_EQ(mask.height, floor.height);
        EXPECT_GT(floor.width * floor.height, 1000);
        // Both flights start or end on each floor: the middle of each true footprint is masked,
        // a point 1 m beside it (across the flight) is not.
        for (const json& s : gt_.at("staircases")) {
            const json& lo = s.at("nosings").front();
            const json& hi = s.at("nosings").back();
            const double cx = 0.25 * (lo["start"][0].get<double>() + lo["end"][0].get<double>() +
                                      hi["start"][0].get<double>() + hi["end"][0].get<double>());
            const double cy = 0.25 * (lo["start"][1].get<double>() + lo["end"][1].get<double>() +
                                      hi["start"][1].get<double>() + hi["end"][1].get<double>());
            EXPECT_EQ(mask.occupancyAt(cx, cy), 100) << stem << " " << s.at("name");
            EXPECT_NE(mask.occupancyAt(cx, cy + 1.6), 100) << stem << " " << s.at("name");
        }
    }
    // The robot walked the floor-0 hall through (5, 5): seen floor around it (the LiDAR's rings
    // leave gaps, and nothing right under the sensor), no obstacle next to it.
    const MapServerMap floor0 = readMapServerMap(out("floor_0.yaml"));
    int cells = 0, free = 0, occupied = 0;
    for (double dx = -1.5; dx <= 1.5; dx += 0.05) {
        for (double dy = -1.5; dy <= 1.5; dy += 0.05) {
            const double r = std::hypot(dx, dy);
            if (r > 1.5) continue;
            const int v = floor0.occupancyAt(5.0 + dx, 5.0 + dy);
            ++cells;
            free += v == 0;
            occupied += v == 100 && r < 0.5;
        }
    }
    EXPECT_GT(free, cells / 5);
    EXPECT_EQ(occupied, 0);
}

TEST_F(ExportTwoFloor, GeoJsonAndSpotFiles) {
    const json geo = readJsonFile(out("graph.geojson"));
    int points = 0, lines = 0;
    for (const json& f : geo.at("features")) {
        (f.at("geometry").at("type") == "Point" ? points : lines)++;
    }
    EXPECT_EQ(points, 2);
    EXPECT_EQ(lines, 4);
    const json spot = readJsonFile(out("staircases_spot.json"));
    ASSERT_GE(spot.at("staircases").size(), 2u);
    // stair_a's origin: bottom centre of its first riser, (2.0, 0.8, 0.0) in the truth. The map is
    // in the frame of the drifting poses handed to the mapper (0.46 m off in y there): the origin
    // is expected where the pose error of the nearest pose carries it.
    const Eigen::Vector3d expected = intoEstimatedFrame({2.0, 0.8, 0.0});
    double best = 1e9;
    for (const json& s : spot.at("staircases")) {
        const json& p = s.at("staircase").at("stair_tform").at("frame_tform_stairs").at("position");
        best = std::min(best, std::hypot(p.at("x").get<double>() - expected.x(),
                                         p.at("y").get<double>() - expected.y()));
    }
    EXPECT_LT(best, 0.15);
    EXPECT_NE(result_.out.find("2 nodes, 4 edges"), std::string::npos) << result_.out;
}

/// stderr holds exactly one line, which mentions `what`.
void expectOneLineNaming(const CliResult& r, const std::string& what) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(ExportCli, BadInputIsOneLineAndExitTwo) {
    const std::string dir = cliScratchDir("export", "bad." + std::to_string(::getpid()));
    fs::create_directories(dir + "/empty");
    const std::string robot = " --robot '" + presetPath("tracked") + "' --out '" + dir + "/out'";
    expectOneLineNaming(runStairmap("export '" + dir + "/empty'" + robot, dir),
                        dir + "/empty/landmarks.json");

    // landmarks.json present, map.bt missing.
    fs::create_directories(dir + "/nobt");
    std::ofstream(dir + "/nobt/landmarks.json") << "{}";
    expectOneLineNaming(runStairmap("export '" + dir + "/nobt'" + robot, dir),
                        dir + "/nobt/map.bt");

    // A profile with a negative limit (checked before the map is read).
    fs::create_directories(dir + "/withbt");
    std::ofstream(dir + "/withbt/landmarks.json") << "{}";
    std::ofstream(dir + "/withbt/map.bt") << "x";
    const std::string bad = dir + "/negative.ini";
    std::ofstream(bad) << "[robot]\nmin_width_m = -0.5\n";
    const CliResult r = runStairmap(
        "export '" + dir + "/withbt' --robot '" + bad + "' --out '" + dir + "/out'", dir);
    expectOneLineNaming(r, bad);
    EXPECT_NE(r.err.find("min_width_m"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace stairmap::test
