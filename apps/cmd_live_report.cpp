// stats.json, the status line and the stdout summary of `stairmap live` (LiveReport.h).
#include <cstdio>

#include "LiveReport.h"
#include "io/json/MapperJson.h"
#include "io/system/ProcessMemory.h"

namespace stairmap::apps {
namespace {

nlohmann::json latencyJson(const live::LatencySummary& s) {
    return {{"count", s.count},
            {"median_ms", 1000.0 * s.median_s},
            {"p95_ms", 1000.0 * s.p95_s},
            {"mean_ms", 1000.0 * s.mean_s},
            {"max_ms", 1000.0 * s.max_s}};
}

}  // namespace

nlohmann::json liveStatsJson(const pipeline::Mapper& mapper, const live::LiveStatus& status,
                             const std::string& source, std::size_t queue_capacity,
                             const std::string& ended) {
    nlohmann::json j = io::mapperStatsToJson(mapper.stats());
    const auto& q = status.queue;
    j["live"] = {
        {"source", source},
        {"lossy", status.lossy},
        {"ended", ended},
        {"elapsed_s", status.elapsed_s},
        {"scans_mapped", status.scans_mapped},
        {"scans_per_s", status.scans_per_s},
        {"lag_s", status.lag_s},
        {"dropped_scans", q.dropped},
        {"landmark_changes", status.landmark_changes},
        {"queue", {{"capacity", queue_capacity}, {"pushed", q.pushed}, {"dropped", q.dropped},
                   {"discarded_on_stop", q.discarded_on_stop}, {"queued", q.queued},
                   {"peak_queued", q.peak_queued}}},
        {"latency", {{"landmark_update", latencyJson(status.update_latency)},
                     {"scan", latencyJson(status.scan_latency)},
                     {"processing", latencyJson(status.processing)},
                     {"queue_wait", latencyJson(status.queue_wait)}}},
        {"source_counters", status.source_counters}};
    j["peak_rss_mb"] = io::peakRssBytes() / 1048576.0;
    j["rss_mb"] = io::currentRssBytes() / 1048576.0;
    j["voxel_map"] = {{"leaves", mapper.voxelMap().numLeaves()},
                      {"memory_mb", mapper.voxelMap().memoryUsageBytes() / 1048576.0}};
    j["landmarks"] = {{"staircases", mapper.landmarks().staircases().size()},
                      {"floors", mapper.landmarks().floors().size()}};
    j["params"] = io::mapperParamsToJson(mapper.params());
    return j;
}

std::string liveStatusLine(const live::LiveStatus& s) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "live: %zu scans, %.1f scans/s, lag %.2f s, dropped %zu, landmarks %zu, "
                  "latency p95 %.0f ms",
                  s.scans_mapped, s.scans_per_s, s.lag_s, s.queue.dropped, s.staircases,
                  1000.0 * s.scan_latency.p95_s);
    return line;
}

void printLiveSummary(const pipeline::Mapper& mapper, const live::LiveStatus& status,
                      const std::string& source, const std::string& ended, const std::string& out) {
    std::printf("stairmap live: %s (%s)\n", ended.c_str(), source.c_str());
    std::printf("  scans %zu in %.1f s, dropped %zu, landmark changes %zu, peak RSS %.0f MB\n",
                status.scans_mapped, status.elapsed_s, status.queue.dropped,
                status.landmark_changes, io::peakRssBytes() / 1048576.0);
    std::printf("  latency scan -> landmark update: median %.0f ms, p95 %.0f ms (%zu updates); "
                "processing median %.0f ms\n",
                1000.0 * status.update_latency.median_s, 1000.0 * status.update_latency.p95_s,
                status.update_latency.count, 1000.0 * status.processing.median_s);
    for (const auto& [name, count] : status.source_counters) {
        if (count > 0) std::printf("  source %s: %zu\n", name.c_str(), count);
    }
    for (const auto& f : mapper.landmarks().floors())
        std::printf("  floor %d: z = %.2f m\n", f.id, f.z);
    for (const auto& s : mapper.landmarks().staircases()) {
        std::printf("  stair #%d: %zu steps, rise %.3f run %.3f width %.2f m, floors %d -> %d, "
                    "seen %d x%s\n",
                    s.id, s.stairs.steps.size(), s.stairs.step_height, s.stairs.step_depth,
                    s.stairs.step_width, s.bottom_floor, s.top_floor, s.observations,
                    s.confirmed ? " (confirmed)" : "");
    }
    std::printf("  outputs in %s\n", out.c_str());
}

}  // namespace stairmap::apps
