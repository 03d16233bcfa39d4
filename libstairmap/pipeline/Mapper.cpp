#include "pipeline/Mapper.h"

#include <chrono>

#include "core/StaircaseTransform.h"

namespace stairmap::pipeline {
namespace {

/// Adds the wall time of its scope to an accumulator [s].
class StageTimer {
public:
    explicit StageTimer(double& total_s) : total_s_(total_s), start_(Clock::now()) {}
    ~StageTimer() { total_s_ += std::chrono::duration<double>(Clock::now() - start_).count(); }
    StageTimer(const StageTimer&) = delete;
    StageTimer& operator=(const StageTimer&) = delete;

private:
    using Clock = std::chrono::steady_clock;
    double& total_s_;
    Clock::time_point start_;
};

constexpr double kTrajectorySpacingM = 0.05;

}  // namespace

Mapper::Mapper(const MapperParams& params) : Mapper(params, LandmarkMap(params.landmarks)) {}

Mapper::Mapper(const MapperParams& params, LandmarkMap landmarks)
    : params_(params),
      voxel_map_(params.map),
      window_(params.scheduling.window_scans, params.scheduling.window_s),
      scheduler_(params.scheduling),
      level_guard_(params.scheduling.max_level_slope_deg),
      transit_recorder_(params.landmarks.floor_merge_tolerance_m),
      detector_(params.detector),
      landmarks_(std::move(landmarks)) {
    if (params_.map.insert_every_n_scans < 1) {
        throw std::invalid_argument("VoxelMapParams.insert_every_n_scans must be >= 1");
    }
}

void Mapper::processScan(const Scan& scan) {
    if (!acceptsLabel(scan)) {
        ++stats_.scans_filtered_label;
        return;
    }
    PointCloud points_world = prepareWorldPoints(scan);
    insertIntoVoxelMap(points_world, scan);
    recordTrajectory(scan);
    window_.push(scan.stamp_s, std::move(points_world));
    // On stairs the scheduler is not consulted, so its counters keep growing and the first scan
    // back on level ground triggers a detection.
    const bool level = level_guard_.update(scan.T_world_robot.translation());
    recordTransit(scan, level);
    if (!level) return;
    if (scheduler_.update(scan.stamp_s, scan.T_world_robot)) detectAround(scan);
}

bool Mapper::acceptsLabel(const Scan& scan) const {
    return params_.sensor.label_filter.empty() || scan.sensor_label == params_.sensor.label_filter;
}

PointCloud Mapper::prepareWorldPoints(const Scan& scan) {
    const StageTimer timer(stats_.times.prepare_s);
    if (stats_.scans == 0) stats_.first_stamp_s = scan.stamp_s;
    stats_.last_stamp_s = scan.stamp_s;
    ++stats_.scans;
    stats_.points_in += scan.points_robot.size();
    const auto min2 = static_cast<float>(params_.sensor.min_range_m * params_.sensor.min_range_m);
    const auto max2 = static_cast<float>(params_.sensor.max_range_m * params_.sensor.max_range_m);
    const Eigen::Isometry3f T_world_robot = scan.T_world_robot.cast<float>();
    PointCloud points_world;
    points_world.reserve(scan.points_robot.size());
    for (const auto& p : scan.points_robot) {
        const float r2 = p.squaredNorm();
        if (!(r2 >= min2 && r2 <= max2)) continue;  // also drops NaN
        points_world.push_back(T_world_robot * p);
    }
    stats_.points_used += points_world.size();
    return points_world;
}

void Mapper::insertIntoVoxelMap(const PointCloud& points_world, const Scan& scan) {
    if ((stats_.scans - 1) % static_cast<std::size_t>(params_.map.insert_every_n_scans) != 0) return;
    const StageTimer timer(stats_.times.voxel_map_s);
    voxel_map_.insertScan(points_world, scan.T_world_robot.translation());
    ++stats_.voxel_insertions;
}

void Mapper::recordTrajectory(const Scan& scan) {
    const Eigen::Vector3d position = scan.T_world_robot.translation();
    if (!trajectory_.empty() &&
        (trajectory_.back().position - position).norm() < kTrajectorySpacingM) {
        return;
    }
    trajectory_.push_back(TrajectorySample{scan.stamp_s, position});
}

void Mapper::recordTransit(const Scan& scan, bool level) {
    // A climb from one floor level to another links the flights it went through to both floors.
    const Eigen::Vector3d floor_position =
        scan.T_world_robot.translation() - Eigen::Vector3d(0.0, 0.0, params_.sensor.robot_height_m);
    const std::optional<FloorTransit> transit =
        transit_recorder_.update(floor_position, level, scan.stamp_s);
    if (!transit) return;
    ++stats_.floor_transits;
    if (landmarks_.addFloorTransit(*transit) && on_changed_) on_changed_(landmarks_);
}

std::optional<double> Mapper::submapFloorZ() const {
    if (!params_.sensor.floor_from_pose) return std::nullopt;
    return -params_.sensor.robot_height_m;
}

void Mapper::detectAround(const Scan& scan) {
    const Eigen::Isometry3d T_world_grav = gravityAlignedFrame(scan.T_world_robot);
    PointCloud submap;
    {
        const StageTimer timer(stats_.times.submap_s);
        submap = window_.extractSubmap(T_world_grav, params_.scheduling.submap_radius_m,
                                       params_.scheduling.submap_leaf_m);
    }
    DetectionResult result;
    DetectorDebug* debug = on_run_ && run_debug_ ? &debug_ : nullptr;
    const double detect_before_s = stats_.times.detect_s;
    {
        const StageTimer timer(stats_.times.detect_s);
        result = detector_.detect(submap, submapFloorZ(), debug);
    }
    ++stats_.detector_runs;
    stats_.submap_points += submap.size();
    DetectionRun run;
    {
        const StageTimer timer(stats_.times.landmarks_s);
        bool changed = false;
        for (const Staircase& staircase : result.staircases) {
            DetectionRecord record =
                addToLandmarks(transformStaircase(staircase, T_world_grav), scan, changed);
            if (on_run_) run.records.push_back(std::move(record));
        }
        const double robot_floor_z =
            scan.T_world_robot.translation().z() - params_.sensor.robot_height_m;
        changed = landmarks_.addRobotFloor(robot_floor_z, scan.stamp_s) || changed;
        if (changed && on_changed_) on_changed_(landmarks_);
    }
    if (!on_run_) return;
    run.scan_index = scan.index;
    run.stamp_s = scan.stamp_s;
    run.T_world_grav = T_world_grav;
    run.submap_radius_m = params_.scheduling.submap_radius_m;
    run.submap = &submap;
    run.result = &result;
    run.debug = debug;
    run.detect_s = stats_.times.detect_s - detect_before_s;
    on_run_(run);
}

DetectionRecord Mapper::addToLandmarks(const Staircase& staircase_world, const Scan& scan,
                                       bool& changed) {
    ++stats_.detections;
    DetectionRecord record;
    record.scan_index = scan.index;
    record.stamp_s = scan.stamp_s;
    record.T_world_robot = scan.T_world_robot;
    record.staircase_world = staircase_world;
    record.update = landmarks_.addDetection(staircase_world, scan.stamp_s);
    if (!record.update.changed) ++stats_.detections_rejected;
    changed = changed || record.update.changed;
    if (on_detection_) on_detection_(record);
    return record;
}

}  // namespace stairmap::pipeline
