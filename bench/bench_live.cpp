// The live runner under load (issue 11): a sensor-like (lossy) source pushes simulated scans at a
// fixed rate into the bounded queue while the mapping thread runs the Mapper; the whole process is
// pinned to ONE core (sched_setaffinity), so source, queue and mapper share it.
//   - VLP-16-like (16 beams x 0.2 deg = 28.8k points) and OS1-64-like (64 x 0.35 deg = 65.8k)
//     scans of a drive through the simulated two-floor building (generation is not timed).
//   BM_Live10Hz: at 10 Hz: latency from a scan's arrival to the end of the processScan that
//     changed the landmarks (median/p95), arrival -> processed for every scan, processing time,
//     dropped scans.
//   BM_LiveMaxRate: the highest input rate with no dropped scan over `kTrialScans` scans: starts
//     at 0.95 / (mean processing time at 10 Hz) and steps down by 10 % until a trial drops none.
//   BM_LiveLongStream: as fast as the mapper goes (lossless), 8 loops of the same area; RSS after
//     the first loop and after the last: memory must stay flat when the area does not grow.
#include <benchmark/benchmark.h>
#include <sched.h>

#include <chrono>
#include <map>
#include <random>
#include <thread>

#include "io/system/ProcessMemory.h"
#include "live/LiveRunner.h"
#include "pipeline/Mapper.h"
#include "sim/BuildingGenerator.h"
#include "sim/ScanSimulator.h"
#include "sim/SensorModel.h"
#include "sim/Trajectory.h"

namespace {

using namespace stairmap;
constexpr double kBaseHeight = 0.35;
constexpr std::size_t kTrialScans = 120;

/// ~12 s of a 10 Hz drive past stair_a's foot in the two-floor building (robot frame scans).
std::vector<Scan> simulateDrive(const sim::SensorParams& sensor) {
    sim::Scene scene;
    sim::addTwoFloorBuilding(scene, sim::BuildingParams{});
    sim::TrajectoryParams tp;
    tp.waypoints = {{6.0, 5.0, 0}, {6.0, 2.5, 0}, {1.5, 2.5, 0}, {1.5, 5.0, 0}, {6.0, 5.0, 0}};
    tp.scan_rate_hz = 10.0;
    tp.base_height_m = kBaseHeight;
    Eigen::Isometry3d T_robot_sensor = Eigen::Isometry3d::Identity();
    T_robot_sensor.translation().z() = 0.3;
    const Eigen::Isometry3f T = T_robot_sensor.cast<float>();
    std::mt19937 rng(3);
    std::vector<Scan> scans;
    for (const auto& sample : sim::sampleTrajectory(tp)) {
        Scan scan;
        scan.index = scans.size();
        scan.T_world_robot = sample.T_world_robot_reported;
        for (const auto& p : sim::simulateScan(scene, sample.T_world_robot_true * T_robot_sensor,
                                               sensor, rng, 0.07 * scan.index))
            scan.points_robot.push_back(T * p);
        scans.push_back(std::move(scan));
    }
    return scans;
}

const std::vector<Scan>& driveFor(const std::string& model) {
    static std::map<std::string, std::vector<Scan>> cache;
    if (auto it = cache.find(model); it != cache.end()) return it->second;
    sim::SensorParams sensor = sim::sensorPreset(model);
    if (model == "os1_64") sensor.horizontal_resolution_deg = 0.35;
    sensor.max_range_m = 40.0;
    return cache.emplace(model, simulateDrive(sensor)).first->second;
}

pipeline::MapperParams benchParams() {  // the wheeled preset, as bench_mapper
    pipeline::MapperParams p;
    p.sensor.robot_height_m = kBaseHeight;
    p.map.insert_every_n_scans = 2;
    p.scheduling.window_scans = 10;
    p.scheduling.window_s = 1.0;
    return p;
}

/// Pushes `count` scans at `rate_hz` (0: as fast as the queue takes them), looping over the drive
/// with increasing stamps.
class PacedSource : public live::LiveSource {
public:
    PacedSource(const std::vector<Scan>& scans, double rate_hz, std::size_t count, bool lossy)
        : scans_(scans), rate_hz_(rate_hz), count_(count), lossy_(lossy) {}
    void run(live::ScanSink& sink, const std::atomic<bool>& stop) override {
        const auto t0 = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < count_ && !stop; ++i) {
            if (rate_hz_ > 0)
                std::this_thread::sleep_until(t0 + std::chrono::duration_cast<std::chrono::nanoseconds>(
                                                       std::chrono::duration<double>(i / rate_hz_)));
            Scan s = scans_[i % scans_.size()];
            s.index = i;
            s.stamp_s = 0.1 * i;  // the log's own 10 Hz time, whatever the push rate
            sink.push(std::move(s));
        }
    }
    bool lossy() const override { return lossy_; }
    std::string describe() const override { return "paced simulator"; }
    std::map<std::string, std::size_t> counters() const override { return {}; }

private:
    const std::vector<Scan>& scans_;
    double rate_hz_;
    std::size_t count_;
    bool lossy_;
};

void pinToOneCore() {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(0, &set);
    sched_setaffinity(0, sizeof set, &set);  // threads started later inherit it
}

live::LiveStatus runTrial(const std::string& model, double rate_hz, std::size_t count, bool lossy,
                          const std::function<void(const live::LiveStatus&)>& tick = {}) {
    pinToOneCore();
    PacedSource source(driveFor(model), rate_hz, count, lossy);
    pipeline::Mapper mapper(benchParams());
    live::LiveRunnerParams params;  // queue of 4 scans
    params.tick_period_s = 0.2;
    live::LiveRunner runner(mapper, source, params);
    if (tick) runner.setTickCallback(tick);
    runner.run();
    return runner.status();
}

void BM_Live10Hz(benchmark::State& state, const std::string& model) {
    driveFor(model);
    for (auto _ : state) {
        const live::LiveStatus s = runTrial(model, 10.0, kTrialScans, true);
        state.SetIterationTime(s.elapsed_s);
        state.counters["update_latency_median_ms"] = 1e3 * s.update_latency.median_s;
        state.counters["update_latency_p95_ms"] = 1e3 * s.update_latency.p95_s;
        state.counters["landmark_updates"] = static_cast<double>(s.update_latency.count);
        state.counters["scan_latency_median_ms"] = 1e3 * s.scan_latency.median_s;
        state.counters["scan_latency_p95_ms"] = 1e3 * s.scan_latency.p95_s;
        state.counters["processing_median_ms"] = 1e3 * s.processing.median_s;
        state.counters["processing_mean_ms"] = 1e3 * s.processing.mean_s;
        state.counters["dropped"] = static_cast<double>(s.queue.dropped);
        state.counters["points_per_scan"] = static_cast<double>(driveFor(model)[0].points_robot.size());
    }
}

void BM_LiveMaxRate(benchmark::State& state, const std::string& model) {
    driveFor(model);
    for (auto _ : state) {
        const live::LiveStatus base = runTrial(model, 10.0, kTrialScans / 2, true);
        double rate = 0.95 / std::max(base.processing.mean_s, 1e-4);
        live::LiveStatus s;
        int trials = 0;
        for (; trials < 15 && rate > 1.0; ++trials, rate *= 0.9) {
            s = runTrial(model, rate, kTrialScans, true);
            if (s.queue.dropped == 0) break;
        }
        state.SetIterationTime(1.0);
        state.counters["max_rate_hz_no_drops"] = rate;
        state.counters["scan_latency_p95_ms_at_max"] = 1e3 * s.scan_latency.p95_s;
        state.counters["trials"] = trials + 1;
    }
}

void BM_LiveLongStream(benchmark::State& state) {
    const std::string model = "vlp16";
    const std::size_t loop = driveFor(model).size(), loops = 8;
    for (auto _ : state) {
        double rss_after_first = 0.0;
        const live::LiveStatus s =
            runTrial(model, 0.0, loop * loops, false, [&](const live::LiveStatus& t) {
                if (rss_after_first == 0.0 && t.scans_mapped >= loop)
                    rss_after_first = io::currentRssBytes() / 1048576.0;
            });
        state.SetIterationTime(s.elapsed_s);
        state.counters["scans"] = static_cast<double>(s.scans_mapped);
        state.counters["rss_mb_after_loop_1"] = rss_after_first;
        state.counters["rss_mb_after_last_loop"] = io::currentRssBytes() / 1048576.0;
        state.counters["scans_per_s"] = s.scans_mapped / s.elapsed_s;
    }
}

BENCHMARK_CAPTURE(BM_Live10Hz, vlp16, "vlp16")->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_Live10Hz, os1_64, "os1_64")->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_LiveMaxRate, vlp16, "vlp16")->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_LiveMaxRate, os1_64, "os1_64")->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_LiveLongStream)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
