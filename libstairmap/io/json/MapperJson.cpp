#include "io/json/MapperJson.h"

#include <cmath>

#include "io/json/StaircaseJson.h"

namespace stairmap::io {
namespace {

nlohmann::json vec3(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

double ms(double s) { return 1000.0 * s; }

}  // namespace

nlohmann::json poseToJson(const Eigen::Isometry3d& T_world_robot) {
    const Eigen::Quaterniond q(T_world_robot.linear());
    return {{"position", vec3(T_world_robot.translation())},
            {"quaternion_xyzw", {q.x(), q.y(), q.z(), q.w()}},
            {"yaw_deg", pipeline::robotYaw(T_world_robot) * 180.0 / M_PI}};
}

nlohmann::json detectionRecordToJson(const pipeline::DetectionRecord& record) {
    return {{"stamp_s", record.stamp_s},
            {"scan_index", record.scan_index},
            {"robot_pose", poseToJson(record.T_world_robot)},
            {"staircase", io::toJson(record.staircase_world)},
            {"landmark_id", record.update.landmark_id},
            {"created", record.update.created},
            {"merged_landmarks", record.update.merged_landmarks}};
}

nlohmann::json mapperStatsToJson(const pipeline::MapperStats& s) {
    const double per_scan = s.scans > 0 ? 1.0 / static_cast<double>(s.scans) : 0.0;
    const double per_run = s.detector_runs > 0 ? 1.0 / static_cast<double>(s.detector_runs) : 0.0;
    return {{"scans", s.scans},
            {"scans_filtered_label", s.scans_filtered_label},
            {"points_in", s.points_in},
            {"points_used", s.points_used},
            {"voxel_insertions", s.voxel_insertions},
            {"detector_runs", s.detector_runs},
            {"mean_submap_points", s.submap_points * per_run},
            {"detections", s.detections},
            {"detections_rejected", s.detections_rejected},
            {"floor_transits", s.floor_transits},
            {"log_duration_s", s.logDuration()},
            {"stage_total_ms",
             {{"prepare", ms(s.times.prepare_s)},
              {"voxel_map", ms(s.times.voxel_map_s)},
              {"submap", ms(s.times.submap_s)},
              {"detect", ms(s.times.detect_s)},
              {"landmarks", ms(s.times.landmarks_s)}}},
            {"stage_mean_ms",
             {{"prepare_per_scan", ms(s.times.prepare_s) * per_scan},
              {"voxel_map_per_insertion",
               s.voxel_insertions ? ms(s.times.voxel_map_s) / s.voxel_insertions : 0.0},
              {"submap_per_run", ms(s.times.submap_s) * per_run},
              {"detect_per_run", ms(s.times.detect_s) * per_run},
              {"landmarks_per_run", ms(s.times.landmarks_s) * per_run}}}};
}

nlohmann::json mapperParamsToJson(const pipeline::MapperParams& p) {
    const auto& m = p.map;
    const auto& sc = p.scheduling;
    return {{"sensor",
             {{"robot_height_m", p.sensor.robot_height_m},
              {"floor_from_pose", p.sensor.floor_from_pose},
              {"label_filter", p.sensor.label_filter},
              {"min_range_m", p.sensor.min_range_m},
              {"max_range_m", p.sensor.max_range_m}}},
            {"map",
             {{"resolution_m", m.resolution_m},
              {"insertion_mode",
               m.insertion_mode == map::VoxelInsertionMode::Endpoints ? "endpoints" : "raycast"},
              {"max_range_m", m.max_range_m},
              {"insert_every_n_scans", m.insert_every_n_scans}}},
            {"scheduling",
             {{"distance_m", sc.distance_m},
              {"angle_deg", sc.angle_deg},
              {"period_s", sc.period_s},
              {"window_scans", sc.window_scans},
              {"window_s", sc.window_s},
              {"submap_radius_m", sc.submap_radius_m},
              {"submap_leaf_m", sc.submap_leaf_m},
              {"max_level_slope_deg", sc.max_level_slope_deg}}}};
}

}  // namespace stairmap::io
