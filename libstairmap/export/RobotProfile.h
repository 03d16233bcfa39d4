#pragma once
// What one robot can climb: the limits a staircase is checked against ([robot] section of
// config/robots/*.ini, loaded by io/config/RobotProfileConfig.h). Defaults describe a generic
// mid-size robot; the presets override them.

#include <string>

namespace stairmap::exporting {

struct RobotProfile {
    std::string name = "robot";          ///< label used in the export files (the INI's file stem)
    double max_rise_m = 0.18;            ///< [m] highest riser it climbs (> 0)
    double min_run_m = 0.25;             ///< [m] shallowest tread it stands on (>= 0)
    double min_width_m = 0.8;            ///< [m] narrowest flight it fits through (>= 0)
    double max_slope_deg = 35.0;         ///< [deg] steepest flight, atan(rise / run), in (0, 90)
    int max_steps_without_landing = 20;  ///< [-] most risers between two landings (>= 1)
    bool can_ascend = true;              ///< it climbs stairs at all
    bool can_descend = true;             ///< it walks/drives down stairs at all
    double footprint_length_m = 0.8;     ///< [m] body length along its heading (> 0)
    double footprint_width_m = 0.5;      ///< [m] body width (> 0)
    double clearance_m = 0.1;            ///< [m] free margin kept around the footprint (>= 0)
    double height_m = 0.7;  ///< [m] body height: obstacles below it block a floor cell (> 0)
};

/// Throws std::invalid_argument "RobotProfile.<field>: <problem>" for an out-of-range field.
void validateRobotProfile(const RobotProfile& profile);

}  // namespace stairmap::exporting
