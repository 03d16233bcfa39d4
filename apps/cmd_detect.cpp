// `stairmap detect CLOUD [--robot-height H] [--config FILE]`: one cloud in, one JSON object out.

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "Commands.h"
#include "core/StairDetector.h"
#include "io/cloud/CloudFile.h"
#include "io/config/DetectorConfig.h"
#include "io/config/ConfigFile.h"
#include "io/json/StaircaseJson.h"

namespace stairmap::apps {

namespace {

constexpr double kMaxRobotHeightM = 100.0;  // anything taller is a typo, not a robot

const char* kDetectHelp =
    "Detect ascending and descending staircases in one point cloud and print them as JSON.\n"
    "\n"
    "Input: .xyz (ASCII x y z per line), .pcd (ascii/binary), .ply (ascii/binary_little_endian),\n"
    "each also gzipped (.xyz.gz, .pcd.gz, .ply.gz), or an MRPT .rawlog (its first 3D\n"
    "observation, converted to the robot frame via sensorPose).\n"
    "The cloud must be in a gravity-aligned robot frame in metres: x forward, y left, z up,\n"
    "origin at the robot body; the floor the robot stands on is at z = -H.\n"
    "Floor height: --robot-height H, else robot_height_m of the config's [detector] section,\n"
    "else estimated from the cloud.\n"
    "\n"
    "Output (stdout, exactly one JSON object; lengths in m, angles in deg, robot frame):\n"
    "  {\"staircases\":[{\"direction\":\"ascending\"|\"descending\",\"num_steps\":k,\n"
    "    \"step_height\":m,\"step_depth\":m,\"step_width\":m,\"slope_deg\":deg,\n"
    "    \"location\":[x,y,z] (centre of the first step edge),\"heading_deg\":deg (direction of\n"
    "    travel up/down the flight, counter-clockwise from +x),\n"
    "    \"left_side\"|\"right_side\":\"wall\"|\"open\"|\"unseen\" (what ends the treads, looking\n"
    "    along the heading; unseen: the view does not cover it, the width may be short there),\n"
    "    \"start_z\":m (height above the robot's floor of the surface the flight starts from:\n"
    "    0 on the robot's floor, else a landing or platform above (+) or below (-) it),\n"
    "    \"steps\":[{\"start\":[x,y,z],\"end\":[x,y,z],...},...] (from the robot's floor outward)}],\n"
    "   \"time_ms\":t (detector only, no file reading),\"floor_z\":m,\"floor_estimated\":bool,\n"
    "   \"num_points\":n (finite points read),\n"
    "   \"input\":{\"cloud\":path,\"config\":path|null,\"robot_height_m\":H|null}}\n"
    "Exit status: 0 on success (also when nothing is found); 2 on bad input or options,\n"
    "with one line on stderr naming the file and the problem.";

struct DetectOptions {
    std::string cloud_path;
    std::optional<double> robot_height_m;
    std::string config_path;
};

io::DetectorConfig loadConfig(const std::string& config_path) {
    if (config_path.empty()) return {};  // built-in defaults
    return io::loadDetectorConfigFile(config_path);
}

/// --robot-height wins over the config; no height at all means "estimate the floor".
std::optional<double> floorHeight(const DetectOptions& options, const io::DetectorConfig& config) {
    const std::optional<double> height = options.robot_height_m ? options.robot_height_m : config.robot_height_m;
    if (!height) return std::nullopt;
    const std::string source = options.robot_height_m ? "--robot-height" : options.config_path + ": robot_height_m";
    if (!std::isfinite(*height) || *height < 0.0 || *height > kMaxRobotHeightM) {
        std::ostringstream message;
        message << source << ": robot height must be a finite number of metres in [0, " << kMaxRobotHeightM
                << "], got " << *height;
        throw std::runtime_error(message.str());
    }
    return -*height;
}

int runDetect(const DetectOptions& options) {
    const io::DetectorConfig config = loadConfig(options.config_path);
    const std::optional<double> floor_z = floorHeight(options, config);
    std::unique_ptr<StairDetector> detector;
    try {
        detector = std::make_unique<StairDetector>(config.params);
    } catch (const std::exception& e) {
        throw std::runtime_error((options.config_path.empty() ? "built-in defaults" : options.config_path) +
                                 ": invalid detector parameters: " + e.what());
    }
    const PointCloud cloud = io::readCloudFile(options.cloud_path);

    const auto start = std::chrono::steady_clock::now();
    const DetectionResult result = detector->detect(cloud, floor_z);
    const auto stop = std::chrono::steady_clock::now();
    const double time_ms = std::chrono::duration<double, std::milli>(stop - start).count();

    nlohmann::json out = io::detectionToJson(result, time_ms);
    out["num_points"] = cloud.size();
    // What the result was made from (STYLE: outputs record their effective settings).
    out["input"] = {{"cloud", options.cloud_path},
                    {"config", options.config_path.empty() ? nlohmann::json() : nlohmann::json(options.config_path)},
                    {"robot_height_m", floor_z ? nlohmann::json(-*floor_z) : nlohmann::json()}};
    std::cout << out.dump() << "\n" << std::flush;
    if (!std::cout) throw std::runtime_error("writing the result to stdout failed");
    return 0;
}

}  // namespace

Command addDetectCommand(CLI::App& app) {
    auto options = std::make_shared<DetectOptions>();
    Command command;
    command.cli = app.add_subcommand("detect", "Detect staircases in one point cloud (prints JSON)");
    command.cli->footer(kDetectHelp);
    command.cli->add_option("CLOUD", options->cloud_path, "Point cloud: .xyz, .pcd, .ply (each optionally .gz) or .rawlog")
        ->required();
    command.cli->add_option("--robot-height", options->robot_height_m,
                            "[m] height of the robot frame origin above the floor it stands on (floor z = -H)");
    command.cli->add_option("--config", options->config_path,
                            "MRPT-style INI file; its [detector] section overrides the built-in defaults");
    command.run = [options, input = command.input]() -> int {
        *input = options->cloud_path;
        return runDetect(*options);
    };
    return command;
}

}  // namespace stairmap::apps
