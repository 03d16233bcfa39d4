// Point-cloud file reading speed (what `stairmap detect` pays before the detector runs), per
// format and encoding, for a 200k-point cloud written to a temporary file.

#include <benchmark/benchmark.h>

#include <filesystem>
#include <random>
#include <string>

#include "io/cloud/CloudFile.h"

namespace {

using stairmap::PointCloud;
using stairmap::io::CloudFileEncoding;

constexpr std::size_t kPoints = 200000;

/// Writes the cloud once per (extension, encoding) and returns the path.
std::string cloudPath(const std::string& extension, CloudFileEncoding encoding) {
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("stairmap_bench_cloud_" + std::to_string(int(encoding)) + extension))
                                 .string();
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(-8.0f, 8.0f);
    PointCloud cloud(kPoints);
    for (auto& p : cloud) p = {u(rng), u(rng), u(rng) / 4};
    stairmap::io::writeCloudFile(path, cloud, encoding);
    return path;
}

void readFile(benchmark::State& state, const std::string& extension, CloudFileEncoding encoding) {
    const std::string path = cloudPath(extension, encoding);
    for (auto _ : state) {
        const PointCloud cloud = stairmap::io::readCloudFile(path);
        benchmark::DoNotOptimize(cloud.data());
    }
    state.SetItemsProcessed(state.iterations() * kPoints);
    std::filesystem::remove(path);
}

void BM_ReadPcdBinary(benchmark::State& s) { readFile(s, ".pcd", CloudFileEncoding::Binary); }
void BM_ReadPcdAscii(benchmark::State& s) { readFile(s, ".pcd", CloudFileEncoding::Ascii); }
void BM_ReadPlyBinary(benchmark::State& s) { readFile(s, ".ply", CloudFileEncoding::Binary); }
void BM_ReadPlyAscii(benchmark::State& s) { readFile(s, ".ply", CloudFileEncoding::Ascii); }
void BM_ReadXyz(benchmark::State& s) { readFile(s, ".xyz", CloudFileEncoding::Ascii); }

BENCHMARK(BM_ReadPcdBinary)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadPcdAscii)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadPlyBinary)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadPlyAscii)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadXyz)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
