#pragma once
// JSON values of the mapper's records (no files here: the writers in io/ and the app do that).

#include <nlohmann/json.hpp>

#include "pipeline/Mapper.h"

namespace stairmap::io {

/// {"position":[x,y,z], "quaternion_xyzw":[qx,qy,qz,qw], "yaw_deg":deg} (world frame).
nlohmann::json poseToJson(const Eigen::Isometry3d& T_world_robot);

/// One line of detections.jsonl: {"stamp_s", "scan_index", "robot_pose", "staircase" (world
/// frame, as detected), "landmark_id" (-1 if rejected), "created", "merged_landmarks"}.
nlohmann::json detectionRecordToJson(const pipeline::DetectionRecord& record);

/// Counters and stage times of a run; times in ms, with per-scan means.
nlohmann::json mapperStatsToJson(const pipeline::MapperStats& stats);

/// The effective [sensor], [map], [scheduling] parameters (for the record in stats.json).
nlohmann::json mapperParamsToJson(const pipeline::MapperParams& params);

}  // namespace stairmap::io
