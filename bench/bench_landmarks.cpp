// Cost of the landmark map: one addDetection (association + fusion + floors) in a building with
// N staircases, and one atomic JSON save of that map. Synthetic flights, seeded noise.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "io/json/LandmarkJson.h"
#include "map/LandmarkMap.h"

namespace {

using stairmap::Staircase;
using stairmap::StairEdge;

/// A 14-step flight at grid cell `cell`, seen with ~1 cm noise.
Staircase flight(int cell, std::mt19937& rng) {
    std::normal_distribution<double> noise(0.0, 0.01);
    const double x0 = 10.0 * (cell % 10), y0 = 10.0 * (cell / 10), z0 = 3.0 * (cell % 3);
    Staircase s;
    for (int i = 0; i < 14; ++i) {
        StairEdge e;
        const double x = x0 + 0.28 * i + noise(rng), z = z0 + 0.17 * (i + 1) + noise(rng);
        e.start = {x, y0 + 0.6 + noise(rng), z};
        e.end = {x, y0 - 0.6 + noise(rng), z};
        e.num_points = 40;
        s.steps.push_back(e);
    }
    s.step_height = 0.17;
    s.step_depth = 0.28;
    s.step_width = 1.2;
    return s;
}

stairmap::LandmarkMap building(int staircases, std::mt19937& rng) {
    stairmap::LandmarkMap map;
    for (int k = 0; k < 3; ++k) {
        for (int c = 0; c < staircases; ++c) map.addDetection(flight(c, rng), k);
    }
    for (int i = 0; i < 30; ++i) map.addRobotFloor(3.0 * (i % 3), i);
    return map;
}

void BM_AddDetection(benchmark::State& state) {
    std::mt19937 rng(1);
    stairmap::LandmarkMap map = building(static_cast<int>(state.range(0)), rng);
    int c = 0;
    for (auto _ : state) {
        const auto update = map.addDetection(flight(c++ % state.range(0), rng), 10.0);
        benchmark::DoNotOptimize(update.landmark_id);
    }
    state.counters["landmarks"] = static_cast<double>(map.staircases().size());
}
BENCHMARK(BM_AddDetection)->Arg(2)->Arg(10)->Arg(50)->Unit(benchmark::kMicrosecond);

void BM_SaveAtomic(benchmark::State& state) {
    std::mt19937 rng(2);
    const stairmap::LandmarkMap map = building(static_cast<int>(state.range(0)), rng);
    const std::string path = "/tmp/stairmap_bench_landmarks_" + std::to_string(::getpid()) + ".json";
    for (auto _ : state) stairmap::io::saveLandmarkMapAtomic(path, map);
    std::remove(path.c_str());
}
BENCHMARK(BM_SaveAtomic)->Arg(2)->Arg(10)->Arg(50)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
