#pragma once
// The run of a turning (spiral) flight at its mid radius, from its edges as measured.
// A spiral's nosings are radial about the column's axis, each turned by the step angle from the one
// below. estimateGeometry's spacing (each edge centre's distance to its neighbour's line) reads
// mid radius x sin(step) there, short of the chord 2 x mid radius x sin(step / 2) by 2-6 % at
// 25-40 deg, and an edge seen only near the column puts its centre inside the mid radius. Here:
// the axis is the point nearest to all edge lines (least squares), the step angle the median of
// the seen edges' pairwise angle steps around it (Theil-Sen; put-back edges are interpolated), the
// outer radius the median of the seen edges' outer ends (as measured over the treads by
// StepExtent). On the two dev sets (96 spirals) the spiral run MAE went 1.66 / 2.04 -> 1.47 / 1.33
// cm; the upper quartile of the outer ends gave 1.54 / 1.45, the largest 1.84 / 1.66 (a tread walk
// can run onto a wall). The inner radius is the lower median of the inner ends (of an even count's
// two middle ones, the nearer): a far or side view hides the inner part of some nosings behind the
// column or the wedges below, so inner ends read long, not short (0.47-0.85 m out on a 0.19-0.26 m
// column: dev3 r0229, r0135, 4-step chains whose upper middle value read their runs 5 cm long). Run
// MAE on dev / dev2 / dev3 (all flights) 0.45 / 0.59 / 0.62 -> 0.41 / 0.58 / 0.58 cm; the lower
// quartile gave 0.42 / 0.56 / 0.56 but read close views short, where the fitted axis is a few cm
// off (dev2 r0228: 1.2 -> 3.7 cm), the smallest 0.43 / 0.63 / 0.61 (session of 2026-12-04,
// afternoon). The Theil-Sen step angle (before: least squares over every edge's angle against its
// index) took the run MAE on dev / dev2 / dev3 0.402 / 0.549 / 0.518 -> 0.395 / 0.543 / 0.506 cm,
// check / check2 0.693 / 0.601 -> 0.684 / 0.580; put-back edges in the pairs too gave 0.397 / 0.551
// / 0.511.

#include <Eigen/Core>
#include <optional>

#include "core/Staircase.h"

namespace stairmap {

struct TurningFlightParams {
    double min_step_angle_deg = 10.0;  ///< [deg] below this per step the flight is straight
    double max_axis_offset_m = 0.15;   ///< [m] an edge's line passes this close to the axis
};

struct TurningFlight {
    Eigen::Vector2d axis = Eigen::Vector2d::Zero();  ///< [m] XY of the column's axis
    double step_angle_rad = 0.0;                     ///< [rad] turn per step (> 0)
    double inner_radius_m = 0.0;                     ///< [m]
    double outer_radius_m = 0.0;                     ///< [m]
    double run_m = 0.0;  ///< [m] chord between consecutive nosings at mid radius
};

/// The turning geometry of `s` (3 edges at least, most of them radial about one axis, turning by
/// at least min_step_angle_deg per step on average), or nothing for a straight flight.
std::optional<TurningFlight> turningFlight(const Staircase& s, const TurningFlightParams& params = {});

/// [m] The chord between consecutive nosings at the mid radius between `inner_radius_m` and t's
/// outer radius: (inner + outer) x sin(step / 2).
double runAtMidRadius(const TurningFlight& t, double inner_radius_m);

}  // namespace stairmap
