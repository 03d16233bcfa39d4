// Rawlog input throughput: RawlogScanSource streaming a synthetic observations-only rawlog
// (per scan a CObservationRobotPose + a 30 000-point CObservationPointCloud), plain and gz, and
// our Velodyne decoding of one real VLP-16 rotation. Reports scans/s and points/s; the source
// keeps a constant number of scans in memory whatever the log length.
#include <benchmark/benchmark.h>
#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <random>
#include <string>

#include "io/rawlog/ObservationToPoints.h"
#include "io/rawlog/RawlogScanSource.h"

namespace {

constexpr int kScans = 50;
constexpr int kPointsPerScan = 30000;

void writeSyntheticRawlog(mrpt::serialization::CArchive& ar) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(-10.f, 10.f);
    for (int i = 0; i < kScans; ++i) {
        const auto stamp = mrpt::Clock::fromDouble(0.1 * i);
        mrpt::obs::CObservationRobotPose pose;
        pose.pose.mean = mrpt::poses::CPose3D(0.1 * i, 0, 0, 0, 0, 0);
        pose.timestamp = stamp;
        auto map = mrpt::maps::CSimplePointsMap::Create();
        for (int k = 0; k < kPointsPerScan; ++k) {
            // mm-rounded like real lidar data (compresses like it)
            map->insertPointFast(std::round(u(rng) * 1000) / 1000, std::round(u(rng) * 1000) / 1000,
                                 std::round(u(rng) * 1000) / 1000);
        }
        mrpt::obs::CObservationPointCloud cloud;
        cloud.pointcloud = map;
        cloud.sensorPose = mrpt::poses::CPose3D(0, 0, 0.5, 0, 0, 0);
        cloud.sensorLabel = "lidar";
        cloud.timestamp = stamp;
        ar << pose << cloud;
    }
}

std::string syntheticRawlog(bool gz) {
    const std::string path = (std::filesystem::temp_directory_path() /
                              (gz ? "stairmap_bench_rawlog.rawlog.gz" : "stairmap_bench_rawlog.rawlog"))
                                 .string();
    if (std::filesystem::exists(path)) return path;
    if (gz) {
        mrpt::io::CFileGZOutputStream f;
        f.open(path, 1);
        auto ar = mrpt::serialization::archiveFrom(f);
        writeSyntheticRawlog(ar);
    } else {
        mrpt::io::CFileOutputStream f(path);
        auto ar = mrpt::serialization::archiveFrom(f);
        writeSyntheticRawlog(ar);
    }
    return path;
}

void BM_RawlogScanSource(benchmark::State& state) {
    const std::string path = syntheticRawlog(state.range(0) != 0);
    std::size_t scans = 0, points = 0;
    for (auto _ : state) {
        stairmap::io::RawlogScanSource source(path);
        while (auto s = source.next()) {
            ++scans;
            points += s->points_robot.size();
        }
    }
    state.counters["scans/s"] = benchmark::Counter(double(scans), benchmark::Counter::kIsRate);
    state.counters["points/s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
    state.SetLabel(state.range(0) ? "gz level 1" : "plain");
}
BENCHMARK(BM_RawlogScanSource)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_VelodyneVlp16Rotation(benchmark::State& state) {
    const std::string path =
        std::string(STAIRMAP_SOURCE_DIR) + "/../shared/data/real/sample_velodyne_vlp16_gps.rawlog";
    mrpt::io::CFileGZInputStream f(path);
    auto ar = mrpt::serialization::archiveFrom(f);
    auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservationVelodyneScan>(ar.ReadObject());
    if (!obs) {
        state.SkipWithError("cannot read the VLP-16 sample rawlog");
        return;
    }
    std::size_t points = 0;
    for (auto _ : state) {
        const auto r = stairmap::io::observationToRobotPoints(*obs);
        points += r.points_robot.size();
        benchmark::DoNotOptimize(r.points_robot.data());
    }
    state.counters["points/s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_VelodyneVlp16Rotation)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
