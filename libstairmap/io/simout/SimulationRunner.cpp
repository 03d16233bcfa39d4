#include "io/simout/SimulationRunner.h"

#include <chrono>
#include <filesystem>
#include <random>

#include "io/cloud/CloudFile.h"
#include "io/json/GroundTruthJson.h"
#include "io/simout/SimOutputs.h"
#include "io/simout/SimRawlogWriter.h"
#include "sim/CloudSampler.h"
#include "sim/ScanSimulator.h"

namespace stairmap::io {

namespace {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

nlohmann::json matrixJson(const Eigen::Isometry3d& T) {
    nlohmann::json rows = nlohmann::json::array();
    for (int r = 0; r < 4; ++r) {
        rows.push_back({T.matrix()(r, 0), T.matrix()(r, 1), T.matrix()(r, 2), T.matrix()(r, 3)});
    }
    return rows;
}

nlohmann::json commonExtra(const sim::SimulationConfig& config) {
    return {{"scene", config.name},
            {"kind", config.kind},
            {"sensor", config.sensor.model},
            {"seed", config.seed},
            {"T_robot_sensor", matrixJson(config.T_robot_sensor)}};
}

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

/// Re-expresses the reported poses in the robot's own frame (RobotRun::T_world_odom); the
/// covariance's position rows turn with the frame's yaw.
void toOdomFrame(std::vector<sim::TrajectorySample>& samples, const Eigen::Isometry3d& T_world_odom) {
    const Eigen::Isometry3d T_odom_world = T_world_odom.inverse();
    Eigen::Matrix<double, 6, 6> J = Eigen::Matrix<double, 6, 6>::Identity();
    J.topLeftCorner<3, 3>() = T_odom_world.linear();
    for (auto& s : samples) {
        s.T_world_robot_reported = T_odom_world * s.T_world_robot_reported;
        s.covariance = J * s.covariance * J.transpose();
    }
}

nlohmann::json runRobot(const sim::SimulationConfig& config, const sim::RobotRun& run, bool single,
                        const fs::path& dir, const SimulationRunOptions& options,
                        SimulationRunSummary& summary, unsigned seed) {
    auto samples = sim::sampleTrajectory(run.trajectory);
    sim::applySway(samples, run.sway);
    sim::applyDrift(samples, run.drift);
    if (!run.T_world_odom.isApprox(Eigen::Isometry3d::Identity())) toOdomFrame(samples, run.T_world_odom);
    const std::string prefix = single ? "" : run.name + "_";
    const fs::path rawlog = dir / (run.name + ".rawlog");
    SimRawlogWriter writer(rawlog.string(), options.gzip_level, config.rawlog_quantum_m);
    std::mt19937 rng(seed);
    const sim::MountedSensor& mounted = run.mounted;
    std::uniform_real_distribution<double> azimuth(0.0, mounted.sensor.horizontal_resolution_deg);
    StampedPoses reported, truth;
    for (const auto& s : samples) {
        const auto t0 = Clock::now();
        auto points = sim::simulateScan(config.scene, s.T_world_robot_true * mounted.T_robot_sensor,
                                        mounted.sensor, rng, azimuth(rng));
        if (config.rawlog_sort_points) sim::quantizeAndSort(points, config.rawlog_quantum_m, true);
        summary.ray_cast_ms += msSince(t0);
        writer.writeScan(s.stamp_s, s.T_world_robot_reported, s.covariance, mounted.T_robot_sensor,
                         points, mounted.label);
        summary.points += points.size();
        ++summary.scans;
        reported.emplace_back(s.stamp_s, s.T_world_robot_reported);
        truth.emplace_back(s.stamp_s, s.T_world_robot_true);
        if (options.progress) {
            options.progress(run.name + ": scan " + std::to_string(reported.size()) + "/" +
                             std::to_string(samples.size()));
        }
    }
    writer.close();
    const fs::path poses = dir / (prefix + "poses.tum");
    const fs::path gt_traj = dir / (prefix + "gt_trajectory.tum");
    writeTumPosesFile(poses.string(), reported);
    writeTumPosesFile(gt_traj.string(), truth);
    summary.files.insert(summary.files.end(), {rawlog.string(), poses.string(), gt_traj.string()});
    nlohmann::json entry = {{"name", run.name},
            {"rawlog", rawlog.filename().string()},
            {"poses", poses.filename().string()},
            {"gt_trajectory", gt_traj.filename().string()},
            {"scans", samples.size()},
            {"sensor", mounted.sensor.model},
            {"T_robot_sensor", matrixJson(mounted.T_robot_sensor)},
            {"base_height_m", run.trajectory.base_height_m}};
    // only for a robot in its own frame: the older datasets' gt.json stay byte-identical
    if (!run.T_world_odom.isApprox(Eigen::Isometry3d::Identity())) entry["T_world_odom"] = matrixJson(run.T_world_odom);
    return entry;
}

void writeClouds(const sim::SimulationConfig& config, const fs::path& dir,
                 const SimulationRunOptions& options, SimulationRunSummary& summary) {
    std::mt19937 rng(config.seed);
    for (std::size_t i = 0; i < config.cloud_poses.size(); ++i) {
        const auto& pose = config.cloud_poses[i];
        const Eigen::Isometry3d T_world_robot =
            sim::robotPoseAt(pose.ground, pose.yaw_deg * M_PI / 180.0, config.base_height_m);
        const auto t0 = Clock::now();
        const auto cloud = sim::simulateRobotCloud(config.scene, T_world_robot, config.T_robot_sensor,
                                                   config.sensor, config.cloud_params, rng);
        summary.ray_cast_ms += msSince(t0);
        const std::string stem = config.name + "_" + std::to_string(config.cloud_first_index + i);
        const fs::path cloud_path = dir / (stem + "." + config.cloud_extension);
        const fs::path gt_path = dir / (stem + ".gt.json");
        writeCloudFile(cloud_path.string(), cloud);
        auto extra = commonExtra(config);
        extra["cloud"] = cloud_path.filename().string();
        extra["T_world_robot"] = matrixJson(T_world_robot);
        writeGroundTruthFile(gt_path.string(),
                             sim::truthInRobotFrame(config.scene.truth(), T_world_robot, pose.ground.z(),
                                                    config.cloud_params.floor_tolerance_m),
                             extra);
        summary.files.insert(summary.files.end(), {cloud_path.string(), gt_path.string()});
        summary.points += cloud.size();
        ++summary.clouds;
        if (options.progress) options.progress(stem + ": " + std::to_string(cloud.size()) + " points");
    }
}
}  // namespace

SimulationRunSummary runSimulation(const sim::SimulationConfig& config, const std::string& out_dir,
                                   const SimulationRunOptions& options) {
    std::error_code ec;
    fs::create_directories(out_dir, ec);
    if (ec || !fs::is_directory(out_dir)) throw std::runtime_error(out_dir + ": cannot create directory");
    SimulationRunSummary summary;
    if (options.write_rawlogs && !config.robots.empty()) {
        auto extra = commonExtra(config);
        extra["robots"] = nlohmann::json::array();
        for (std::size_t r = 0; r < config.robots.size(); ++r) {
            extra["robots"].push_back(runRobot(config, config.robots[r], config.robots.size() == 1,
                                               out_dir, options, summary,
                                               config.seed + 1000u * static_cast<unsigned>(r)));
        }
        const fs::path gt = fs::path(out_dir) / "gt.json";
        writeGroundTruthFile(gt.string(), config.scene.truth(), extra);
        summary.files.push_back(gt.string());
    }
    if (options.write_clouds) writeClouds(config, out_dir, options, summary);
    return summary;
}

}  // namespace stairmap::io
