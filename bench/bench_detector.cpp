// Detector time per cloud on accumulated-LiDAR-like clouds of 20k .. 1M points over an
// 8 x 8 x 4 m room (floor, four walls, ceiling) holding an 8-step staircase. Clouds are generated
// deterministically here (fixed seed): points uniform on the surfaces, thinned with range like an
// accumulated spinning LiDAR (keep probability (2 m / r)^2), 1 cm Gaussian noise.
// Run: build/bin/bench_detector  (reports mean/median/stddev over repetitions; target: median
// <= 1.5 ms at 60k points on one core, growing no worse than linearly).
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "core/StairDetector.h"

namespace {

using stairmap::PointCloud;

struct Quad {
    Eigen::Vector3d origin, u, v;  // origin + s*u + t*v, s,t in [0,1]
    double area() const { return u.cross(v).norm(); }
};

/// Room 8 x 8 x 4 m around the robot (robot frame, floor at z = -0.5) with a staircase ahead.
std::vector<Quad> roomWithStairs() {
    const double f = -0.5, h = 4.0, rise = 0.17, run = 0.28, w = 1.2;
    std::vector<Quad> q;
    q.push_back({{-4, -4, f}, {8, 0, 0}, {0, 8, 0}});       // floor
    q.push_back({{-4, -4, f + h}, {8, 0, 0}, {0, 8, 0}});   // ceiling
    q.push_back({{-4, -4, f}, {8, 0, 0}, {0, 0, h}});       // walls
    q.push_back({{-4, 4, f}, {8, 0, 0}, {0, 0, h}});
    q.push_back({{-4, -4, f}, {0, 8, 0}, {0, 0, h}});
    q.push_back({{4, -4, f}, {0, 8, 0}, {0, 0, h}});
    for (int k = 1; k <= 8; ++k) {  // 8 risers from x = 1.5, the last tread is a landing
        const double x = 1.5 + (k - 1) * run, z = f + k * rise;
        const double depth = k == 8 ? 4.0 - x : run;
        q.push_back({{x, -w / 2, z - rise}, {0, 0, rise}, {0, w, 0}});
        q.push_back({{x, -w / 2, z}, {depth, 0, 0}, {0, w, 0}});
    }
    return q;
}

PointCloud makeCloud(std::size_t n) {
    const auto quads = roomWithStairs();
    std::vector<double> areas;
    for (const auto& q : quads) areas.push_back(q.area());
    std::mt19937 rng(42);
    std::discrete_distribution<int> pick(areas.begin(), areas.end());
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    std::normal_distribution<double> noise(0.0, 0.01);
    PointCloud cloud;
    cloud.reserve(n);
    while (cloud.size() < n) {
        const Quad& q = quads[pick(rng)];
        const Eigen::Vector3d p = q.origin + u01(rng) * q.u + u01(rng) * q.v;
        const double r = std::max(0.5, p.norm());
        if (u01(rng) > std::min(1.0, (2.0 / r) * (2.0 / r))) continue;
        cloud.push_back((p + Eigen::Vector3d(noise(rng), noise(rng), noise(rng))).cast<float>());
    }
    std::shuffle(cloud.begin(), cloud.end(), rng);  // accumulation order is not spatial order
    return cloud;
}

const PointCloud& cachedCloud(std::size_t n) {
    static std::map<std::size_t, PointCloud> cache;
    auto it = cache.find(n);
    if (it == cache.end()) it = cache.emplace(n, makeCloud(n)).first;
    return it->second;
}

void BM_Detect(benchmark::State& state) {
    const PointCloud& cloud = cachedCloud(static_cast<std::size_t>(state.range(0)));
    const stairmap::StairDetector detector;
    std::size_t found = 0, steps = 0;
    for (auto _ : state) {
        const auto result = detector.detect(cloud, -0.5);
        found = result.staircases.size();
        steps = found ? result.staircases.front().steps.size() : 0;
        benchmark::DoNotOptimize(result);
    }
    state.counters["points"] = static_cast<double>(cloud.size());
    state.counters["staircases"] = static_cast<double>(found);
    state.counters["steps"] = static_cast<double>(steps);
}

BENCHMARK(BM_Detect)
    ->Arg(20000)
    ->Arg(60000)
    ->Arg(200000)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(7)
    ->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
