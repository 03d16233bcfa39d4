// Simulator cost: one scan of each sensor model in the two-floor building (~60 primitives), and
// a single-stair scene. Target: a VLP-16 scan at 0.2 deg well under 100 ms.

#include <benchmark/benchmark.h>

#include "sim/BuildingGenerator.h"
#include "sim/ScanSimulator.h"
#include "sim/StairGenerators.h"
#include "sim/Trajectory.h"

namespace {

using namespace stairmap::sim;

const Scene& building() {
    static const Scene scene = [] {
        Scene s;
        addTwoFloorBuilding(s, BuildingParams{});
        return s;
    }();
    return scene;
}

void runScan(benchmark::State& state, SensorParams sensor) {
    const Eigen::Isometry3d T_world_sensor = robotPoseAt({4.0, 4.0, 0.0}, 0.3, 0.6);
    std::mt19937 rng(1);
    std::size_t points = 0;
    for (auto _ : state) {
        const auto scan = simulateScan(building(), T_world_sensor, sensor, rng);
        points = scan.size();
        benchmark::DoNotOptimize(scan.data());
    }
    state.counters["points"] = static_cast<double>(points);
    state.counters["primitives"] = static_cast<double>(building().primitives().size());
}

void BM_Vlp16Scan_0p2deg(benchmark::State& state) {
    SensorParams p = vlp16();
    p.horizontal_resolution_deg = 0.2;
    runScan(state, p);
}
void BM_Os1_64Scan_0p35deg(benchmark::State& state) {
    SensorParams p = os1_64();
    p.horizontal_resolution_deg = 0.35;
    runScan(state, p);
}
void BM_Hdl32Scan_0p2deg(benchmark::State& state) {
    SensorParams p = hdl32();
    p.horizontal_resolution_deg = 0.2;
    runScan(state, p);
}
void BM_DepthCamera_320x200(benchmark::State& state) {
    SensorParams p = depthCamera();
    p.image_width = 320;
    p.image_height = 200;
    runScan(state, p);
}

BENCHMARK(BM_Vlp16Scan_0p2deg)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Os1_64Scan_0p35deg)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Hdl32Scan_0p2deg)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DepthCamera_320x200)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
