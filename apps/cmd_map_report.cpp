// stats.json and the stdout summary of `stairmap map` (MapReport.h).
#include <cstdio>

#include "MapReport.h"
#include "io/json/MapperJson.h"
#include "io/system/ProcessMemory.h"

namespace stairmap::apps {

nlohmann::json mapStatsJson(const pipeline::Mapper& mapper, const io::RawlogScanSource& source,
                            const pipeline::MapperParams& params, const MapRunTimes& times) {
    const auto& st = mapper.stats();
    nlohmann::json j = io::mapperStatsToJson(st);
    j["read_ms"] = 1000.0 * times.read_s;
    j["output_ms"] = 1000.0 * times.output_s;
    j["processing_s"] = times.processing_s;
    j["real_time_factor"] = times.processing_s > 0 ? st.logDuration() / times.processing_s : 0.0;
    j["peak_rss_mb"] = io::peakRssBytes() / 1048576.0;
    j["voxel_map"] = {{"leaves", mapper.voxelMap().numLeaves()},
                      {"memory_mb", mapper.voxelMap().memoryUsageBytes() / 1048576.0}};
    j["landmarks"] = {{"staircases", mapper.landmarks().staircases().size()},
                      {"floors", mapper.landmarks().floors().size()}};
    const auto& ss = source.stats();
    j["source"] = {{"scans_read", ss.scans_read},
                   {"skipped_no_pose", ss.skipped_no_pose},
                   {"skipped_label", ss.skipped_label},
                   {"unsupported", ss.unsupported},
                   {"non_finite_dropped", ss.non_finite_dropped}};
    j["params"] = io::mapperParamsToJson(params);
    return j;
}

void printMapSummary(const pipeline::Mapper& mapper, const io::RawlogScanSource& source,
                     const MapRunTimes& times, const std::string& out,
                     const std::optional<std::string>& error, int signal) {
    const auto& st = mapper.stats();
    std::printf("stairmap map: %s\n", signal  ? "STOPPED by signal"
                                      : error ? "STOPPED at damaged rawlog"
                                              : "done");
    std::printf(
        "  scans %zu (%zu points), skipped without pose %zu, log %.1f s, processed in %.2f s"
        " (%.1fx real time)\n",
        st.scans, st.points_in, source.stats().skipped_no_pose, st.logDuration(),
        times.processing_s, times.processing_s > 0 ? st.logDuration() / times.processing_s : 0.0);
    for (const auto& [type, count] : source.stats().unsupported) {
        std::printf("  unsupported observations: %s x %zu\n", type.c_str(), count);
    }
    std::printf("  detector runs %zu, detections %zu, voxel leaves %zu, peak RSS %.0f MB\n",
                st.detector_runs, st.detections, mapper.voxelMap().numLeaves(),
                io::peakRssBytes() / 1048576.0);
    for (const auto& f : mapper.landmarks().floors())
        std::printf("  floor %d: z = %.2f m\n", f.id, f.z);
    for (const auto& s : mapper.landmarks().staircases()) {
        std::printf(
            "  stair #%d: %zu steps, rise %.3f run %.3f width %.2f m, floors %d -> %d, "
            "seen %d x%s\n",
            s.id, s.stairs.steps.size(), s.stairs.step_height, s.stairs.step_depth,
            s.stairs.step_width, s.bottom_floor, s.top_floor, s.observations,
            s.confirmed ? " (confirmed)" : "");
    }
    std::printf("  outputs in %s\n", out.c_str());
}

}  // namespace stairmap::apps
