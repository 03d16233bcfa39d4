#include "io/simout/RandomSetWriter.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "io/cloud/CloudFile.h"
#include "io/json/GroundTruthJson.h"
#include "sim/CloudSampler.h"
#include "sim/RandomCloud.h"

namespace stairmap::io {

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

json matrixJson(const Eigen::Isometry3d& T) {
    json rows = json::array();
    for (int r = 0; r < 4; ++r)
        rows.push_back({T.matrix()(r, 0), T.matrix()(r, 1), T.matrix()(r, 2), T.matrix()(r, 3)});
    return rows;
}

json flightJson(const sim::FlightSpec& f) {
    json j = {{"spiral", f.spiral}, {"descending", f.descending}, {"steps", f.steps},
              {"rise_m", f.rise_m}, {"run_m", f.run_m}, {"width_m", f.width_m},
              {"distance_m", f.distance_m}, {"bearing_deg", f.bearing_deg},
              {"heading_deg", f.heading_deg}, {"open_risers", f.open_risers},
              {"offset_steps", f.offset_steps}, {"offset_by_steps", f.offset_by_steps}};
    if (f.spiral) {
        j.update({{"column_radius_m", f.column_radius_m}, {"step_angle_deg", f.step_angle_deg},
                  {"clockwise", f.clockwise}, {"balusters", f.balusters}});
    } else {
        j.update({{"left", sim::sideKindName(f.left)}, {"right", sim::sideKindName(f.right)},
                  {"debris_count", f.debris_count}});
    }
    return j;
}

json specJson(const sim::RandomSceneSpec& spec) {
    const auto& s = spec.sensor;
    json flights = json::array(), extras = json::array();
    for (const auto& f : spec.flights) flights.push_back(flightJson(f));
    for (const auto& n : spec.extras) {
        extras.push_back({{"type", n.type}, {"distance_m", n.distance_m}, {"bearing_deg", n.bearing_deg},
                          {"heading_deg", n.heading_deg}, {"width_m", n.width_m}, {"slope_deg", n.slope_deg},
                          {"height_m", n.height_m}, {"run_m", n.run_m}, {"tiers", n.tiers}});
    }
    return {{"sensor", {{"kind", sim::sensorKindName(s.kind)}, {"model", s.model},
                        {"base_height_m", s.base_height_m}, {"mount_height_m", s.mount_height_m},
                        {"pitch_deg", s.pitch_deg}, {"scans", s.scans},
                        {"path_length_m", s.path_length_m}, {"tilt_std_deg", s.tilt_std_deg},
                        {"cell_m", s.cell_m}}},
            {"flights", flights}, {"extras", extras}};
}

/// Writes one scene; returns its point count.
std::size_t writeOne(const fs::path& dir, std::uint64_t seed, int index, int& attempts) {
    sim::RandomCloud rc = sim::makeRandomCloud(seed, index);
    sim::quantizeAndSort(rc.cloud, 1.0 / 512.0, true);
    char stem[64];
    std::snprintf(stem, sizeof(stem), "r%04d_%s", index, sim::familyName(rc.spec.family).c_str());
    const fs::path cloud_path = dir / (std::string(stem) + ".pcd.gz");
    writeCloudFile(cloud_path.string(), rc.cloud);
    json extra = {{"kind", sim::familyName(rc.spec.family)},
                  {"sensor", rc.spec.sensor.model},
                  {"sensor_kind", sim::sensorKindName(rc.spec.sensor.kind)},
                  {"generator", "random"},
                  {"generator_version", sim::kRandomGeneratorVersion},
                  {"seed", seed},
                  {"index", index},
                  {"attempts", rc.attempts},
                  {"seen_nosings", rc.seen_nosings},
                  {"points", rc.cloud.size()},
                  {"cloud", cloud_path.filename().string()},
                  {"T_robot_sensor", matrixJson(rc.T_robot_sensor)},
                  {"scene_spec", specJson(rc.spec)}};
    writeGroundTruthFile((dir / (std::string(stem) + ".gt.json")).string(), rc.truth, extra);
    attempts = rc.attempts;
    return rc.cloud.size();
}
}  // namespace

RandomSetSummary writeRandomSet(const std::string& out_dir, const RandomSetOptions& options) {
    if (options.count < 0 || options.jobs < 1 || options.first_index < 0)
        throw std::invalid_argument("random set: count >= 0, first index >= 0 and jobs >= 1 needed");
    std::error_code ec;
    fs::create_directories(out_dir, ec);
    if (ec || !fs::is_directory(out_dir)) throw std::runtime_error(out_dir + ": cannot create directory");
    const auto t0 = std::chrono::steady_clock::now();
    RandomSetSummary summary;
    std::atomic<int> next{0};
    std::mutex mutex;
    std::exception_ptr failure;
    auto worker = [&]() {
        for (int i = next++; i < options.count; i = next++) {
            try {
                int attempts = 1;
                const std::size_t points = writeOne(out_dir, options.seed, options.first_index + i, attempts);
                std::lock_guard<std::mutex> lock(mutex);
                ++summary.clouds;
                summary.points += points;
                if (attempts > 1) ++summary.redrawn;
                if (options.progress)
                    options.progress("scene " + std::to_string(summary.clouds) + "/" +
                                     std::to_string(options.count) + ": " + std::to_string(points) + " points");
            } catch (...) {
                std::lock_guard<std::mutex> lock(mutex);
                if (!failure) failure = std::current_exception();
                next = options.count;
            }
        }
    };
    std::vector<std::thread> threads;
    for (int j = 1; j < options.jobs; ++j) threads.emplace_back(worker);
    worker();
    for (auto& t : threads) t.join();
    if (failure) std::rethrow_exception(failure);
    summary.generate_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return summary;
}

}  // namespace stairmap::io
