#pragma once
// The mapping pipeline: scan + pose in -> voxel map + rolling window -> (when scheduled)
// gravity-aligned submap -> detector (both directions) -> world frame -> landmark map.
// No paths, no printing: results leave through callbacks and accessors.

#include <Eigen/Geometry>
#include <functional>
#include <vector>

#include "core/Scan.h"
#include "core/StairDetector.h"
#include "map/LandmarkMap.h"
#include "map/VoxelMap.h"
#include "pipeline/LevelGuard.h"
#include "pipeline/MapperParams.h"
#include "pipeline/MapperStats.h"
#include "pipeline/Scheduler.h"
#include "pipeline/Submap.h"
#include "pipeline/TransitRecorder.h"

namespace stairmap::pipeline {

/// One raw detection and where it went (a line of detections.jsonl).
struct DetectionRecord {
    std::size_t scan_index = 0;
    double stamp_s = 0.0;                         ///< [s]
    Eigen::Isometry3d T_world_robot = Eigen::Isometry3d::Identity();
    Staircase staircase_world;                    ///< as detected, in the world frame
    LandmarkUpdate update;                        ///< landmark it went to (-1 when rejected)
};

/// One scheduled detector run, as it happened (for viewers and rawlog annotation). The pointers are
/// valid only during the callback.
struct DetectionRun {
    std::size_t scan_index = 0;
    double stamp_s = 0.0;                                  ///< [s]
    Eigen::Isometry3d T_world_grav = Eigen::Isometry3d::Identity();  ///< the submap's frame
    double submap_radius_m = 0.0;                          ///< [m] horizontal cut of the submap
    const PointCloud* submap = nullptr;                    ///< grav frame
    const DetectionResult* result = nullptr;               ///< grav frame
    const DetectorDebug* debug = nullptr;                  ///< grav frame; null unless asked for
    std::vector<DetectionRecord> records;                  ///< where each detection went
    double detect_s = 0.0;                                 ///< [s] wall time of detect()
};

/// A trajectory sample kept for outputs (one per >= 5 cm of travel, so memory follows the area).
struct TrajectorySample {
    double stamp_s = 0.0;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< [m] world
};

class Mapper {
public:
    using DetectionCallback = std::function<void(const DetectionRecord&)>;
    using LandmarksChangedCallback = std::function<void(const LandmarkMap&)>;
    using DetectionRunCallback = std::function<void(const DetectionRun&)>;

    /// Starts an empty landmark map. Throws std::invalid_argument naming a bad parameter.
    explicit Mapper(const MapperParams& params);
    /// Continues `landmarks` (e.g. loaded with --map-in); it keeps its ids.
    Mapper(const MapperParams& params, LandmarkMap landmarks);

    void setDetectionCallback(DetectionCallback cb) { on_detection_ = std::move(cb); }
    void setLandmarksChangedCallback(LandmarksChangedCallback cb) { on_changed_ = std::move(cb); }
    /// Called after every detector run (also when it found nothing), once the landmark map has
    /// taken its detections. with_debug: the detector also fills a DetectorDebug record (extra
    /// time per run; the results are the same).
    void setDetectionRunCallback(DetectionRunCallback cb, bool with_debug = false) {
        on_run_ = std::move(cb);
        run_debug_ = with_debug;
    }

    /// The per-scan step. Scans must come in time order.
    void processScan(const Scan& scan);

    const map::VoxelMap& voxelMap() const { return voxel_map_; }
    const LandmarkMap& landmarks() const { return landmarks_; }
    const std::vector<TrajectorySample>& trajectory() const { return trajectory_; }
    const MapperStats& stats() const { return stats_; }
    const MapperParams& params() const { return params_; }

private:
    bool acceptsLabel(const Scan& scan) const;
    PointCloud prepareWorldPoints(const Scan& scan);
    void insertIntoVoxelMap(const PointCloud& points_world, const Scan& scan);
    void recordTrajectory(const Scan& scan);
    void recordTransit(const Scan& scan, bool level);
    void detectAround(const Scan& scan);
    DetectionRecord addToLandmarks(const Staircase& staircase_world, const Scan& scan,
                                   bool& changed);
    std::optional<double> submapFloorZ() const;

    MapperParams params_;
    map::VoxelMap voxel_map_;
    ScanWindow window_;
    Scheduler scheduler_;
    LevelGuard level_guard_;
    TransitRecorder transit_recorder_;
    StairDetector detector_;
    LandmarkMap landmarks_;
    std::vector<TrajectorySample> trajectory_;
    MapperStats stats_;
    DetectionCallback on_detection_;
    LandmarksChangedCallback on_changed_;
    DetectionRunCallback on_run_;
    bool run_debug_ = false;
    DetectorDebug debug_;  ///< scratch for run_debug_
};

}  // namespace stairmap::pipeline
