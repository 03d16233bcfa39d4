// Detector time per cloud on accumulated LiDAR clouds of 20k .. 1M points in an 8 x 8 x 4 m room
// (floor, four walls, ceiling) holding an 8-step staircase with side walls.
// The clouds come from the simulator: VLP-16 scans at 0.2 deg (~29k returns each) taken while the
// robot walks 2.4 m towards the flight, each with a little pitch/roll sway (a legged gait), all
// expressed in the gravity-aligned frame of the last pose, then randomly subsampled to exactly N
// points kept in scan order. So the density is LiDAR-like: dense rings near the robot, sparse far
// away. Argument -60000: the same 60k points shuffled (worst case for memory locality).
// The counters report what was found, so a timing of a run that finds nothing shows up.
// Run: build/bin/bench_detector  (target: median <= 1.5 ms at 60k points on one core, growing no
// worse than linearly).
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <random>
#include <vector>

#include "core/StairDetector.h"
#include "core/TopView.h"
#include "sim/ScanSimulator.h"
#include "sim/StairGenerators.h"
#include "sim/Trajectory.h"

namespace {

using stairmap::PointCloud;
namespace sim = stairmap::sim;

constexpr double kBaseHeightM = 0.35;  // robot frame origin above the floor
constexpr double kMountZM = 0.25;      // LiDAR above the robot frame origin
constexpr double kPi = 3.14159265358979323846;

sim::Scene roomWithStairs() {
    sim::Scene scene;
    sim::addFloor(scene, {-4.0, -4.0}, {4.0, 4.0}, 0.0);
    const double t = 0.1, h = 4.0;
    scene.add(sim::makeAxisAlignedBox({-4 - t, -4 - t, h}, {4 + t, 4 + t, h + t}));  // ceiling
    scene.add(sim::makeAxisAlignedBox({-4 - t, -4 - t, 0}, {-4, 4 + t, h}));
    scene.add(sim::makeAxisAlignedBox({4, -4 - t, 0}, {4 + t, 4 + t, h}));
    scene.add(sim::makeAxisAlignedBox({-4, -4 - t, 0}, {4, -4, h}));
    scene.add(sim::makeAxisAlignedBox({-4, 4, 0}, {4, 4 + t, h}));
    sim::StraightStairParams stair;
    stair.origin = {0.6, 0.0, 0.0};
    stair.landing_depth_m = 1.0;
    sim::addStraightStair(scene, stair);
    return scene;
}

/// Scans along the walk (-3.2, 0.3) -> (-0.8, 0), all in the frame of the last robot pose.
PointCloud makeCloud(std::size_t n) {
    static const sim::Scene scene = roomWithStairs();
    sim::SensorParams sensor = sim::vlp16();
    sensor.horizontal_resolution_deg = 0.2;
    sensor.dropout_probability = 0.02;
    const int scans = static_cast<int>(n / 25000) + 1;  // a scan has ~29k returns in the room
    const Eigen::Vector3d first(-3.2, 0.3, 0.0), last(-0.8, 0.0, 0.0);
    const Eigen::Isometry3d T_last_world = sim::robotPoseAt(last, 0.0, kBaseHeightM).inverse();
    std::mt19937 rng(42);
    std::normal_distribution<double> sway_rad(0.0, 2.0 * kPi / 180.0);
    PointCloud cloud;
    for (int k = 0; k < scans; ++k) {
        const double f = scans == 1 ? 1.0 : static_cast<double>(k) / (scans - 1);
        const Eigen::Isometry3d T_world_robot =
            sim::robotPoseAt(first + f * (last - first), 0.0, kBaseHeightM);
        Eigen::Isometry3d T_robot_sensor = Eigen::Isometry3d::Identity();
        T_robot_sensor.translation() = Eigen::Vector3d(0, 0, kMountZM);
        T_robot_sensor.linear() = (Eigen::AngleAxisd(sway_rad(rng), Eigen::Vector3d::UnitY()) *
                                   Eigen::AngleAxisd(sway_rad(rng), Eigen::Vector3d::UnitX()))
                                      .toRotationMatrix();
        const Eigen::Isometry3d T_world_sensor = T_world_robot * T_robot_sensor;
        const Eigen::Isometry3f T_last_sensor = (T_last_world * T_world_sensor).cast<float>();
        for (const auto& p : sim::simulateScan(scene, T_world_sensor, sensor, rng, 0.07 * k))
            cloud.push_back(T_last_sensor * p);
    }
    // Exactly n points: a random subset, kept in scan (firing) order as an accumulated cloud is.
    if (cloud.size() > n) {
        std::vector<std::size_t> keep(cloud.size());
        for (std::size_t i = 0; i < keep.size(); ++i) keep[i] = i;
        std::shuffle(keep.begin(), keep.end(), rng);
        keep.resize(n);
        std::sort(keep.begin(), keep.end());
        PointCloud subset;
        subset.reserve(n);
        for (std::size_t i : keep) subset.push_back(cloud[i]);
        cloud.swap(subset);
    }
    return cloud;
}

/// The same points in random order: the worst case for the top view's random grid updates (a
/// cloud merged from unordered sources).
PointCloud shuffled(PointCloud cloud) {
    std::mt19937 rng(7);
    std::shuffle(cloud.begin(), cloud.end(), rng);
    return cloud;
}

/// Clouds by size; a negative size asks for the shuffled cloud of that many points.
const PointCloud& cachedCloud(long n) {
    static std::map<long, PointCloud> cache;
    auto it = cache.find(n);
    if (it == cache.end()) {
        PointCloud c = makeCloud(static_cast<std::size_t>(std::abs(n)));
        it = cache.emplace(n, n < 0 ? shuffled(std::move(c)) : std::move(c)).first;
    }
    return it->second;
}

void BM_Detect(benchmark::State& state) {
    const PointCloud& cloud = cachedCloud(state.range(0));
    const stairmap::StairDetector detector;
    std::size_t found = 0, steps = 0;
    double rise = 0.0;
    for (auto _ : state) {
        const auto result = detector.detect(cloud, -kBaseHeightM);
        found = result.staircases.size();
        steps = found ? result.staircases.front().steps.size() : 0;
        rise = found ? result.staircases.front().step_height : 0.0;
        benchmark::DoNotOptimize(result);
    }
    state.counters["points"] = static_cast<double>(cloud.size());
    state.counters["staircases"] = static_cast<double>(found);
    state.counters["steps"] = static_cast<double>(steps);
    state.counters["rise_mm"] = 1000.0 * rise;  // truth: 170 mm
}

/// The same detection filling a DetectorDebug record (what `stairmap view` asks for): the cost of
/// the record compared with BM_Detect, which passes none (and must not be slower for it).
void BM_DetectDebug(benchmark::State& state) {
    const PointCloud& cloud = cachedCloud(state.range(0));
    const stairmap::StairDetector detector;
    stairmap::DetectorDebug debug;
    std::size_t found = 0;
    for (auto _ : state) {
        const auto result = detector.detect(cloud, -kBaseHeightM, &debug);
        found = result.staircases.size();
        benchmark::DoNotOptimize(result);
    }
    state.counters["points"] = static_cast<double>(cloud.size());
    state.counters["staircases"] = static_cast<double>(found);
    state.counters["candidates"] = static_cast<double>(debug.candidates.size());
    state.counters["lines"] =
        static_cast<double>(debug.lines_ascending.size() + debug.lines_descending.size());
    state.counters["rejected"] = static_cast<double>(debug.rejected.size());
}

/// The first pre-processing stage alone (the largest share of a detection).
void BM_TopView(benchmark::State& state) {
    const PointCloud& cloud = cachedCloud(state.range(0));
    stairmap::TopViewParams params;  // the detector's settings for a floor at -kBaseHeightM
    const stairmap::DetectorParams d;
    params.leaf_m = d.leaf_size_m;
    params.max_range_m = d.max_range_m;
    params.z_lo = -kBaseHeightM - d.max_depth_below_floor_m;
    params.z_hi = -kBaseHeightM + d.max_height_above_floor_m;
    params.edge_min_dz_m = d.edge_min_dz_m;
    params.edge_spill_dz_m = d.edge_spill_dz_m;
    params.edge_spill_max_dz_m = d.min_step_height_m;
    params.ground_z_lo = -kBaseHeightM - d.floor_tolerance_m;
    params.ground_z_hi = -kBaseHeightM + d.floor_tolerance_m;
    std::vector<stairmap::TopViewCell> cells;
    for (auto _ : state) {
        stairmap::buildTopView(cloud, params, cells);
        benchmark::DoNotOptimize(cells.data());
    }
    state.counters["points"] = static_cast<double>(cloud.size());
    state.counters["candidates"] = static_cast<double>(cells.size());
}
BENCHMARK(BM_TopView)->Arg(60000)->Arg(-60000)->Unit(benchmark::kMillisecond);

// Median of 7 repetitions: the machine is shared, single runs are noisy.
BENCHMARK(BM_Detect)
    ->Arg(20000)
    ->Arg(60000)
    ->Arg(200000)
    ->Arg(1000000)
    ->Arg(-60000)  // 60k points in random order
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(7)
    ->ReportAggregatesOnly(true);

BENCHMARK(BM_DetectDebug)
    ->Arg(20000)
    ->Arg(60000)
    ->Arg(200000)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(7)
    ->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
