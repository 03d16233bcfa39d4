#pragma once
// Counters and per-stage times of one mapping run (what stats.json reports).

#include <cstddef>

namespace stairmap::pipeline {

/// Accumulated wall time per stage of the per-scan step [s].
struct StageTimes {
    double prepare_s = 0.0;    ///< range crop + transform to world
    double voxel_map_s = 0.0;  ///< OctoMap insertion
    double submap_s = 0.0;     ///< window -> gravity-aligned submap
    double detect_s = 0.0;     ///< StairDetector::detect
    double landmarks_s = 0.0;  ///< association/fusion/floors
    double total() const { return prepare_s + voxel_map_s + submap_s + detect_s + landmarks_s; }
};

struct MapperStats {
    std::size_t scans = 0;                ///< scans mapped
    std::size_t scans_filtered_label = 0; ///< scans skipped by [sensor] label_filter
    std::size_t points_in = 0;            ///< points of the mapped scans (robot frame)
    std::size_t points_used = 0;          ///< after the [sensor] range crop
    std::size_t voxel_insertions = 0;     ///< scans inserted into the voxel map
    std::size_t detector_runs = 0;        ///< scheduled detections
    std::size_t submap_points = 0;        ///< summed over detector runs
    std::size_t detections = 0;           ///< staircases returned by the detector
    std::size_t detections_rejected = 0;  ///< detections the landmark map did not accept
    std::size_t floor_transits = 0;  ///< climbs between floor levels given to the landmark map
    double first_stamp_s = 0.0;           ///< [s] stamp of the first mapped scan
    double last_stamp_s = 0.0;            ///< [s] stamp of the last mapped scan
    StageTimes times;

    double logDuration() const { return scans > 0 ? last_stamp_s - first_stamp_s : 0.0; }
};

}  // namespace stairmap::pipeline
