#pragma once
// The numbers a planner needs about one flight, measured from a landmark's canonical steps
// (map/LandmarkTypes.h: world frame, steps bottom to top, each edge a nosing).

#include <Eigen/Core>
#include <vector>

#include "map/LandmarkTypes.h"

namespace stairmap::exporting {

/// A level part of the flight between two runs of steps (a mid-flight landing), or its ends.
struct Landing {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< [m] world, on the walking surface
    double length_m = 0.0;                             ///< [m] along the flight's uphill heading
    double width_m = 0.0;                              ///< [m] across it
};

struct FlightGeometry {
    double rise_m = 0.0, run_m = 0.0, width_m = 0.0;  ///< [m] means (landmark's estimate)
    double slope_deg = 0.0;                           ///< [deg] atan(rise / run)
    /// [m] sample standard deviations of the per-step rises, runs and edge lengths (0 with
    /// fewer than two values): how much the steps disagree with the mean.
    double rise_std_m = 0.0, run_std_m = 0.0, width_std_m = 0.0;
    int risers = 0;  ///< nosings = risers (the top nosing is the upper floor's edge)
    int max_risers_between_landings = 0;
    int observed_risers = 0;         ///< nosings the landmark holds (risers minus the inferred)
    int inferred_risers_bottom = 0;  ///< risers added below the lowest seen one (extendToFloors)
    int inferred_risers_top = 0;     ///< risers added above the highest seen one
    double heading_rad = 0.0;        ///< uphill direction, counter-clockwise from world +x
    Eigen::Vector3d bottom = Eigen::Vector3d::Zero();  ///< [m] foot of the first riser (centre)
    Eigen::Vector3d top = Eigen::Vector3d::Zero();     ///< [m] centre of the top nosing
    double length_m = 0.0;              ///< [m] 3D length of the flight, bottom to top
    std::vector<Landing> mid_landings;  ///< level parts inside the flight, bottom to top
};

/// A spacing between consecutive nosings above `landing_run_factor` x the median run is a
/// landing. Precondition: at least one step.
FlightGeometry measureFlight(const StaircaseLandmark& landmark, double landing_run_factor = 1.8);

/// A flight seen in part (the detector often sees only the lower steps, while the robot's climb
/// linked the landmark to both floors) continued with its rise and run to the floors it joins:
/// `bottom` moves down the slope to bottom_z, `top` up to top_z (continuous positions), the risers
/// grow by the rounded number of missing rises, added to the first / last run between landings.
/// A floor closer than half a rise to the seen end changes nothing; pass NaN for an unknown floor.
void extendToFloors(FlightGeometry& flight, double bottom_z, double top_z);

/// Unit vector of the uphill heading in the XY plane.
inline Eigen::Vector2d headingVector(double heading_rad) {
    return {std::cos(heading_rad), std::sin(heading_rad)};
}

}  // namespace stairmap::exporting
