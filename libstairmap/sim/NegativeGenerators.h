#pragma once
// Scenes that contain NO staircase under the paper's definition, to count false positives:
// a furnished room, a ramp (5-15 deg), a single curb, a 1-2 step stage, bleachers whose tiers are too
// tall to be steps (>= 0.35 m). They add solids only; the truth gets no staircase.

#include <Eigen/Core>
#include <string>

#include "sim/Scene.h"

namespace stairmap::sim {

struct NegativeParams {
    std::string type = "room";      ///< room | ramp | curb | stage | bleachers
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< [m] foot of the feature, on the floor
    double heading_deg = 0.0;       ///< [deg] direction the feature rises towards
    double width_m = 4.0;           ///< [m] across the feature
    double ramp_slope_deg = 10.0;   ///< [deg] ramp inclination (5..15 in the bundled set)
    double ramp_length_m = 4.0;     ///< [m] horizontal length of the ramp
    double curb_height_m = 0.15;    ///< [m]
    int stage_steps = 2;            ///< steps up to the stage (1 or 2: too few for a staircase)
    double stage_rise_m = 0.18;     ///< [m]
    double stage_run_m = 0.30;      ///< [m]
    int bleacher_tiers = 4;
    double bleacher_rise_m = 0.45;  ///< [m] tier height (>= 0.35: well above any rise, not a step)
    double bleacher_run_m = 0.80;   ///< [m] tier depth
};

/// Throws std::invalid_argument naming the field if a parameter is out of range.
void validate(const NegativeParams& params);

/// Adds the feature (and a floor around it). Throws for an unknown type.
void addNegative(Scene& scene, const NegativeParams& params);

}  // namespace stairmap::sim
