// `stairmap sim SCENE.ini --out DIR [--seed N] [--cloud-only|--rawlog-only]`: the LiDAR stair-scene
// simulator; `stairmap sim --random N --seed S --out DIR [--jobs J]`: the randomised benchmark
// (sim/RandomScene.h). Scene INI keys and output formats: docs/simulator.md.

#include <iostream>
#include <optional>
#include <string>

#include "Commands.h"
#include "io/config/SceneIni.h"
#include "io/simout/RandomSetWriter.h"
#include "io/simout/SimulationRunner.h"
#include "sim/RandomScene.h"

namespace stairmap::apps {

namespace {

const char* kSimHelp =
    "Simulate a LiDAR (VLP-16, OS1-64, HDL-32) or depth camera in a parametric stair scene.\n"
    "\n"
    "Outputs in --out DIR (created, never wiped):\n"
    "  robots ([trajectory]): <name>.rawlog (MRPT observations-only, gzipped: per scan a\n"
    "    CObservationRobotPose 'robot_pose' then a CObservationPointCloud in the sensor frame),\n"
    "    poses.tum (poses handed to the mapper, with drift), gt_trajectory.tum (true poses),\n"
    "    gt.json (world frame: every staircase's nosings, rise, run, width; floor heights);\n"
    "    several robots: <robot>.rawlog, <robot>_poses.tum, <robot>_gt_trajectory.tum.\n"
    "  clouds ([clouds] poses): <name>_<i>.<format> (pcd, ply, xyz, optionally .gz; robot\n"
    "    frame, accumulated scans) and <name>_<i>.gt.json (truth in the same robot frame).\n"
    "  --random N: N clouds drawn by the randomised benchmark generator instead of a scene file\n"
    "    (r<index>_<family>.pcd.gz + .gt.json; the same --seed gives the same set).\n"
    "Exit status: 0 on success, 2 on a bad scene file or option (one line on stderr).";

struct SimOptions {
    std::string scene_path;
    std::string out_dir;
    std::optional<unsigned> seed;
    bool cloud_only = false;
    bool rawlog_only = false;
    int gzip_level = 6;
    bool quiet = false;
    int random_count = 0;
    int first_index = 0;
    int jobs = 1;
    bool print_version = false;
};

int runRandom(const SimOptions& options) {
    io::RandomSetOptions set;
    set.seed = options.seed.value_or(1);
    set.count = options.random_count;
    set.first_index = options.first_index;
    set.jobs = options.jobs;
    if (!options.quiet) set.progress = [](const std::string& line) { std::cerr << line << "\r"; };
    const auto summary = io::writeRandomSet(options.out_dir, set);
    if (!options.quiet) std::cerr << "\n";
    std::cout << "random set seed " << set.seed << " (generator v" << sim::kRandomGeneratorVersion
              << "): " << summary.clouds << " clouds, " << summary.points << " points ("
              << (summary.clouds ? summary.points / summary.clouds : 0) << " per cloud), "
              << summary.redrawn << " redrawn, " << summary.generate_ms / 1000.0 << " s with "
              << set.jobs << " job(s), in " << options.out_dir << "\n";
    return 0;
}

int runSim(const SimOptions& options) {
    if (options.print_version) {
        std::cout << sim::kRandomGeneratorVersion << "\n";
        return 0;
    }
    if (options.random_count > 0) {
        if (!options.scene_path.empty())
            throw std::invalid_argument("sim: give a scene file or --random N, not both");
        if (options.out_dir.empty()) throw std::invalid_argument("sim: --out is required");
        return runRandom(options);
    }
    if (options.scene_path.empty() || options.out_dir.empty())
        throw std::invalid_argument("sim: a scene file and --out are required (or --random N --out DIR)");
    auto config = io::loadSimulationConfig(options.scene_path);
    if (options.seed) config.seed = *options.seed;
    io::SimulationRunOptions run;
    run.write_clouds = !options.rawlog_only;
    run.write_rawlogs = !options.cloud_only;
    run.gzip_level = options.gzip_level;
    if (!options.quiet) run.progress = [](const std::string& line) { std::cerr << line << "\r"; };
    const auto summary = io::runSimulation(config, options.out_dir, run);
    if (!options.quiet) std::cerr << "\n";
    const double per_ray_unit = summary.scans + summary.clouds * config.cloud_params.scans_per_cloud;
    std::cout << "scene " << config.name << ": " << summary.scans << " rawlog scans, "
              << summary.clouds << " clouds, " << summary.points << " points, ray casting "
              << (per_ray_unit > 0 ? summary.ray_cast_ms / per_ray_unit : 0.0) << " ms/scan\n";
    for (const auto& file : summary.files) std::cout << "  wrote " << file << "\n";
    return 0;
}

}  // namespace

Command addSimCommand(CLI::App& app) {
    auto options = std::make_shared<SimOptions>();
    Command command;
    command.cli = app.add_subcommand("sim", "Simulate a LiDAR stair scene (rawlogs, clouds, ground truth)");
    command.cli->footer(kSimHelp);
    command.cli->add_option("scene", options->scene_path, "Scene INI file (config/scenes/*.ini)");
    command.cli->add_option("--out,-o", options->out_dir, "Output directory");
    command.cli->add_option("--random", options->random_count,
                            "Write N clouds of the randomised benchmark instead of a scene")
        ->check(CLI::Range(1, 100000));
    command.cli->add_option("--first-index", options->first_index, "--random: index of the first scene")
        ->check(CLI::Range(0, 100000000));
    command.cli->add_option("--jobs,-j", options->jobs, "--random: worker threads")
        ->check(CLI::Range(1, 64));
    command.cli->add_flag("--random-version", options->print_version,
                          "Print the random generator's version (cache key) and exit");
    command.cli->add_option("--seed", options->seed, "Override the scene's noise seed");
    auto* cloud_only = command.cli->add_flag("--cloud-only", options->cloud_only,
                                             "Write only the single clouds");
    command.cli->add_flag("--rawlog-only", options->rawlog_only, "Write only the robots' rawlogs")
        ->excludes(cloud_only);
    command.cli->add_option("--gzip-level", options->gzip_level, "Rawlog gzip level")
        ->check(CLI::Range(1, 9));
    command.cli->add_flag("--quiet,-q", options->quiet, "No progress on stderr");
    command.run = [options, input = command.input]() -> int {
        *input = options->scene_path;
        return runSim(*options);
    };
    return command;
}

}  // namespace stairmap::apps
