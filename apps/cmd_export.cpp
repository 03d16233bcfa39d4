// `stairmap export`: stairs for planners from a map directory (landmarks.json + map.bt).
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "Commands.h"
#include "export/FloorGraph.h"
#include "export/FloorGrid.h"
#include "export/SpotStaircase.h"
#include "export/StairMask.h"
#include "io/config/RobotProfileConfig.h"
#include "io/export/GraphJson.h"
#include "io/export/MapServerFiles.h"
#include "io/export/SpotJson.h"
#include "io/json/LandmarkJson.h"
#include "io/system/AtomicFile.h"
#include "map/VoxelMap.h"

namespace stairmap::apps {
namespace {

namespace fs = std::filesystem;
using exporting::FloorGrid;

struct ExportOptions {
    std::string map_dir, out;
    std::vector<std::string> robots;
    bool quiet = false;
};

std::string requireFile(const std::string& dir, const std::string& name, const char* what) {
    const std::string path = (fs::path(dir) / name).string();
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw std::runtime_error(path + ": not found (" + what + "; is " + dir +
                                 " an output directory of `stairmap map`?)");
    }
    return path;
}

std::vector<exporting::RobotProfile> loadProfiles(const std::vector<std::string>& paths) {
    std::vector<exporting::RobotProfile> profiles;
    std::set<std::string> names;
    for (const std::string& path : paths) {
        profiles.push_back(io::loadRobotProfile(path));
        if (!names.insert(profiles.back().name).second) {
            throw std::runtime_error(path + ": robot name '" + profiles.back().name +
                                     "' is used by another --robot file");
        }
    }
    return profiles;
}

std::map<int, FloorGrid> floorGrids(const map::VoxelMap& voxels, const std::vector<Floor>& floors,
                                    const std::vector<exporting::RobotProfile>& profiles) {
    exporting::FloorRasterParams params;
    params.resolution_m = voxels.resolution();
    params.robot_height_m = 0.0;  // the tallest robot decides what blocks a cell
    for (const auto& p : profiles)
        params.robot_height_m = std::max(params.robot_height_m, p.height_m);
    const PointCloud centres = voxels.occupiedVoxelCentres();
    std::map<int, FloorGrid> grids;
    for (const Floor& f : floors) grids[f.id] = exporting::rasteriseFloor(centres, f.z, params);
    return grids;
}

/// Footprints of the flights that start or end on a floor.
std::vector<exporting::FlightGeometry> flightsOn(int floor_id, const LandmarkMap& landmarks) {
    std::vector<exporting::FlightGeometry> out;
    for (const auto& s : landmarks.staircases()) {
        if (s.stairs.steps.empty()) continue;
        if (s.bottom_floor == floor_id || s.top_floor == floor_id) {
            out.push_back(exporting::flightBetweenFloors(s, landmarks.floors()));
        }
    }
    return out;
}

void printSummary(const exporting::FloorGraph& graph, const std::map<int, FloorGrid>& grids,
                  const std::string& out) {
    std::printf("stairmap export: %zu nodes, %zu edges\n", graph.nodes.size(), graph.edges.size());
    for (const auto& [id, g] : grids) {
        std::printf("  floor %d: z = %.2f m, map %d x %d cells at %.3f m\n", id, g.floor_z, g.width,
                    g.height, g.resolution_m);
    }
    for (const auto& e : graph.edges) {
        std::printf("  edge %d: stair #%d %-4s node %d -> %d, %.2f m:", e.id, e.staircase_id,
                    exporting::travelName(e.travel), e.from, e.to, e.length_m);
        for (const auto& r : e.robots) {
            std::printf(" %s=%s", r.robot.c_str(), r.verdict.traversable ? "yes" : "no");
        }
        std::printf("\n");
    }
    std::printf("  outputs in %s\n", out.c_str());
}

int runExport(const ExportOptions& opt) {
    const std::string landmarks_path =
        requireFile(opt.map_dir, "landmarks.json", "the landmark map");
    const std::string voxels_path = requireFile(opt.map_dir, "map.bt", "the voxel map");
    const auto profiles = loadProfiles(opt.robots);
    const LandmarkMap landmarks = io::loadLandmarkMap(landmarks_path);
    const map::VoxelMap voxels = map::VoxelMap::load(voxels_path);
    const auto grids = floorGrids(voxels, landmarks.floors(), profiles);
    const auto graph =
        exporting::buildFloorGraph(landmarks.staircases(), landmarks.floors(), grids, profiles);

    fs::create_directories(opt.out);
    const auto outPath = [&opt](const std::string& name) {
        return (fs::path(opt.out) / name).string();
    };
    io::writeTextFileAtomic(outPath("graph.json"),
                            io::graphToJson(graph, profiles, opt.map_dir).dump(2) + "\n");
    io::writeTextFileAtomic(outPath("graph.geojson"), io::graphToGeoJson(graph).dump(2) + "\n");
    for (const auto& [id, grid] : grids) {
        const std::string stem = "floor_" + std::to_string(id);
        io::saveMapServerMap(opt.out, stem, grid);
        io::saveMapServerMap(opt.out, stem + "_stairs",
                             exporting::stairMask(grid, flightsOn(id, landmarks)));
    }
    std::vector<exporting::SpotStaircase> spot;
    for (const auto& s : landmarks.staircases()) {
        for (auto& st : exporting::toSpotStaircases(s)) spot.push_back(std::move(st));
    }
    io::writeTextFileAtomic(outPath("staircases_spot.json"),
                            io::spotStaircasesToJson(spot).dump(2) + "\n");
    if (!opt.quiet) printSummary(graph, grids, opt.out);
    return 0;
}

}  // namespace

Command addExportCommand(CLI::App& app) {
    auto opt = std::make_shared<ExportOptions>();
    Command command;
    command.cli = app.add_subcommand(
        "export",
        "Stairs for planners from a `stairmap map` output directory (landmarks.json,\n"
        "map.bt): graph.json, graph.geojson (Nav2 Route Server), per floor\n"
        "floor_<id>.pgm/.yaml and floor_<id>_stairs.pgm/.yaml (map_server format),\n"
        "staircases_spot.json (Spot StaircaseWithLandings). docs/export.md.\n"
        "Exit codes: 0 ok; 2 bad arguments/input (one line naming the file).");
    command.cli->add_option("map_dir", opt->map_dir, "output directory of `stairmap map`")
        ->required();
    command.cli
        ->add_option("--robot", opt->robots,
                     "robot profile INI ([robot] section; "
                     "config/robots/*.ini); repeat for several robots")
        ->required();
    command.cli->add_option("--out", opt->out, "output directory (created if needed)")->required();
    command.cli->add_flag("--quiet", opt->quiet, "no summary on stdout");
    command.run = [opt]() -> int { return runExport(*opt); };
    return command;
}

}  // namespace stairmap::apps
