#pragma once
// JSON form of detected staircases (the `stairmap detect` output contract) via nlohmann-json.
//
// A staircase object (all lengths [m], angles [deg], points in the frame the staircase is given in):
//   {"direction":"ascending"|"descending", "num_steps":k, "step_height":m, "step_depth":m,
//    "step_width":m, "slope_deg":deg, "location":[x,y,z], "heading_deg":deg,
//    "left_side":"wall"|"open"|"unseen", "right_side":...,   (looking along heading_deg)
//    "steps":[{"start":[x,y,z], "end":[x,y,z], "num_points":n,
//              "cov_rho_theta":[[c00,c01],[c10,c11]]}, ...]}
// num_points and cov_rho_theta are extras (rho [m], theta [rad]); readers accept them as optional.
// left_side / right_side (core/StepExtent.h) are optional for readers: absent = "unseen".

#include <nlohmann/json.hpp>
#include <string>

#include "core/StairDetector.h"
#include "core/Staircase.h"

namespace stairmap::io {

nlohmann::json toJson(const Staircase& staircase);

/// object[key] as a side ("wall", "open", "unseen"); absent = Unseen (older files). Throws
/// std::runtime_error naming field.key for any other value.
StairSide optionalSide(const nlohmann::json& object, const std::string& field,
                       const std::string& key);

/// Validating inverse of toJson. Throws std::runtime_error naming the offending field
/// (e.g. "staircase.steps[2].end: expected an array of 3 finite numbers"). num_steps, if
/// present, must equal the number of steps. slope_rad/heading_rad come from slope_deg/heading_deg.
Staircase staircaseFromJson(const nlohmann::json& json);

/// The `stairmap detect` output: {"staircases":[...], "time_ms":t, "floor_z":m,
/// "floor_estimated":bool}. time_ms is the detector's run time [ms].
nlohmann::json detectionToJson(const DetectionResult& result, double time_ms);

}  // namespace stairmap::io
