#pragma once
// A landmark in Boston Dynamics Spot's staircase convention (bosdyn/api/stairs.proto,
// StaircaseWithLandings): the stairs frame has its origin at the bottom centre of the first
// riser, X up the stairs, Y to the left facing up, Z against gravity. Steps are nosings ("edge
// centres") in that frame, lowest first; landings are boxes given by their centre pose in the
// stairs frame and half extents. A flight with mid-flight landings becomes one Spot staircase per
// run of steps, the landing shared as the top of one and the bottom of the next.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "map/LandmarkTypes.h"

namespace stairmap::exporting {

struct SpotStep {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< [m] nosing centre, stairs frame
    Eigen::Vector2d north =
        Eigen::Vector2d::UnitX();  ///< unit, up the stairs, perpendicular to the edge
    double width_m = 0.0;
};

struct SpotLanding {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< [m] stairs frame (axes as the stairs)
    double extent_x_m = 0.0, extent_y_m = 0.0;         ///< [m] half sizes
};

struct SpotStaircase {
    std::string id;                                          ///< "stairmap-<landmark id>-<run>"
    Eigen::Vector3d origin_world = Eigen::Vector3d::Zero();  ///< [m] world position of the origin
    double yaw_rad = 0.0;  ///< rotation of the stairs frame about world Z
    double average_rise_m = 0.0, average_run_m = 0.0, average_width_m = 0.0;
    std::vector<SpotStep> steps;
    SpotLanding bottom_landing, top_landing;
    bool confirmed = false;
};

struct SpotParams {
    double landing_length_m = 1.0;    ///< [m] depth of the end landings (nothing measures them)
    double landing_run_factor = 1.8;  ///< [-] a nosing spacing above this x the run is a landing
};

/// One or more Spot staircases for one landmark (empty for a landmark without steps).
std::vector<SpotStaircase> toSpotStaircases(const StaircaseLandmark& landmark,
                                            const SpotParams& params = {});

}  // namespace stairmap::exporting
