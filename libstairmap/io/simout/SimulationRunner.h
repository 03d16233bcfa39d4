#pragma once
// Runs a loaded SimulationConfig and writes its outputs (what `stairmap sim` does):
//   per robot:  <robot>.rawlog, poses.tum (reported poses), gt_trajectory.tum (true poses)
//               (with several robots: <robot>_poses.tum, <robot>_gt_trajectory.tum), and gt.json;
//   per cloud pose: <name>_<i>.<pcd|ply|xyz> (robot frame) and <name>_<i>.gt.json (robot frame).

#include <functional>
#include <string>
#include <vector>

#include "sim/SimulationConfig.h"

namespace stairmap::io {

struct SimulationRunOptions {
    bool write_rawlogs = true;   ///< robots' rawlogs + trajectories + gt.json
    bool write_clouds = true;    ///< single accumulated clouds + their gt
    int gzip_level = 6;          ///< 1..9 for the rawlogs
    /// Called after each scan/cloud with a one-line progress message (may be empty).
    std::function<void(const std::string&)> progress;
};

struct SimulationRunSummary {
    std::vector<std::string> files;  ///< every file written, in order
    std::size_t scans = 0;           ///< rawlog scans simulated
    std::size_t clouds = 0;          ///< single clouds written
    std::size_t points = 0;          ///< points written in all
    double ray_cast_ms = 0.0;        ///< [ms] total time spent casting rays
};

/// Creates out_dir if needed (never wipes it) and writes the outputs. Throws std::runtime_error
/// naming the file on any I/O failure.
SimulationRunSummary runSimulation(const sim::SimulationConfig& config, const std::string& out_dir,
                                   const SimulationRunOptions& options = {});

}  // namespace stairmap::io
