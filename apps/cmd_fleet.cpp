// `stairmap fleet --ros2 --robot A --robot B ...`: the live fleet map (issue 13, item 2). Subscribes
// to each robot's /<robot>/stairmap/staircases (what `stairmap live --ros2 --robot-name <robot>`
// publishes), aligns and fuses the maps into the first robot's frame (fleetlive/LiveFleetMap.h)
// and publishes /fleet/stairmap/staircases and /fleet/stairmap/markers. A robot that goes silent
// keeps its landmarks; one that restarts replaces them. Runs until SIGINT/SIGTERM (exit 0) or
// --duration. --out DIR: the fleet map as files (landmarks.json, alignment.json, provenance.json,
// as `stairmap merge` writes them), rewritten on every change.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "Commands.h"
#include "fleetlive/LiveFleetMap.h"
#include "io/config/MapperConfig.h"
#include "io/json/FleetJson.h"
#include "io/json/LandmarkJson.h"
#include "io/system/StopSignals.h"
#include "map/LandmarkMap.h"
#include "ros2/Ros2LandmarkPublisher.h"
#include "ros2/Ros2StaircaseSubscriber.h"

namespace stairmap::apps {
namespace {

struct FleetOptions {
    std::vector<std::string> robots;
    std::string config;
    std::string out;  ///< empty: no files
    std::string frame_id = "map";
    std::string fleet_name = "fleet";
    double duration_s = 0.0;
    bool ros2 = false;
    bool quiet = false;
};

void printStatus(const FleetOptions& opt, const fleetlive::LiveFleetMap& fleet) {
    std::cerr << "stairmap fleet: " << fleet.fleetMap().staircases.size() << " staircase(s) in the fleet map\n";
    for (std::size_t r = 0; r < opt.robots.size(); ++r) {
        const fleetlive::RobotStatus& s = fleet.status()[r];
        std::cerr << "  " << opt.robots[r] << ": "
                  << (s.has_map ? std::to_string(s.landmarks) + " staircase(s), " : std::string("no map yet"))
                  << (s.has_map ? (s.in_fleet_map ? "in the fleet map" : "not in the fleet map") : "")
                  << (s.note.empty() ? "" : " (" + s.note + ")") << "\n";
    }
}

/// The fleet map as `merge` writes it (docs/merge.md), robots named instead of paths; only robots
/// in the fleet map are in alignment.json. Each file is replaced atomically.
void writeOutputs(const FleetOptions& opt, const fleetlive::LiveFleetMap& fleet, const LandmarkParams& params) {
    namespace fs = std::filesystem;
    fs::create_directories(opt.out);
    const fs::path dir(opt.out);
    io::saveLandmarkStateAtomic((dir / "landmarks.json").string(), fleet.fleetMap(), params);
    std::vector<io::AlignmentRecord> records;
    for (std::size_t r = 0; r < opt.robots.size(); ++r) {
        const fleetlive::RobotStatus& s = fleet.status()[r];
        if (s.in_fleet_map) records.push_back({opt.robots[r], *s.T_fleet_robot, s.sigma, s.pairs});
    }
    io::saveAlignment((dir / "alignment.json").string(), records);
    io::saveProvenance((dir / "provenance.json").string(), fleet.provenance(), opt.robots);
}

int runFleet(const FleetOptions& opt, std::string& input) {
    if (!opt.ros2) throw std::invalid_argument("choose a transport: --ros2 (the only one so far)");
    if (opt.robots.empty()) throw std::invalid_argument("--robot: name at least one robot");
    input = opt.config;
    if (!opt.out.empty()) std::filesystem::create_directories(opt.out);  // fails before subscribing
    const LandmarkParams params =
        opt.config.empty() ? LandmarkParams{} : io::loadMapperParams(opt.config).landmarks;
    fleetlive::LiveFleetMap fleet(opt.robots.size(), params);
    ros2::Ros2StaircaseSubscriber subscriber(opt.robots);
    ros2::Ros2PublisherOptions publish;
    publish.frame_id = opt.frame_id;
    publish.robot_name = opt.fleet_name;
    ros2::Ros2LandmarkPublisher publisher(publish);
    io::StopSignals signals;
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    std::size_t malformed = 0;
    while (!signals.received() && (opt.duration_s <= 0.0 || elapsed() < opt.duration_s)) {
        double stamp = -1.0;
        for (auto& received : subscriber.poll(0.2)) {
            try {
                fleet.update(received.robot, std::move(received.state));
                stamp = std::max(stamp, received.stamp_s);
            } catch (const std::invalid_argument& e) {
                std::cerr << "stairmap fleet: warning: robot " << opt.robots[received.robot] << ": " << e.what() << "\n";
            }
        }
        if (subscriber.malformed() > malformed) {
            malformed = subscriber.malformed();
            std::cerr << "stairmap fleet: warning: " << subscriber.lastProblem() << "\n";
        }
        if (stamp < 0.0) continue;
        const LandmarkMap fleet_map(fleet.fleetMap(), params);
        publisher.publish(fleet_map.staircases(), fleet_map.floors(), stamp);
        if (!opt.out.empty()) writeOutputs(opt, fleet, params);
        if (!opt.quiet) printStatus(opt, fleet);
    }
    publisher.flush(1.0);
    return 0;
}

}  // namespace

Command addFleetCommand(CLI::App& app) {
    auto opt = std::make_shared<FleetOptions>();
    Command command;
    CLI::App* cmd = app.add_subcommand(
        "fleet",
        "Live fleet map over ROS 2: subscribe to /<robot>/stairmap/staircases of each --robot, align the "
        "maps to the first robot's frame from shared staircases, fuse them and publish "
        "/fleet/stairmap/staircases and /fleet/stairmap/markers. Silent robots keep their landmarks. "
        "Runs until SIGINT/SIGTERM or --duration (exit 0).");
    command.cli = cmd;
    cmd->add_flag("--ros2", opt->ros2, "over ROS 2 (required: the only transport)");
    cmd->add_option("--robot", opt->robots, "robot name (repeat; the first sets the fleet frame)")->required();
    cmd->add_option("--config", opt->config, "INI file: [landmarks] parameters of the fusion");
    cmd->add_option("--out", opt->out,
                    "directory: landmarks.json, alignment.json, provenance.json of the fleet map, "
                    "rewritten on every change (as `merge` writes them; robots named, not paths)");
    cmd->add_option("--frame-id", opt->frame_id, "frame_id of what is published (default map)");
    cmd->add_option("--fleet-name", opt->fleet_name, "namespace of the fleet topics (default fleet)");
    cmd->add_option("--duration", opt->duration_s, "[s] stop after this long (default: until a signal)");
    cmd->add_flag("--quiet", opt->quiet, "no status on stderr");
    command.run = [opt, input = command.input] { return runFleet(*opt, *input); };
    return command;
}

}  // namespace stairmap::apps
