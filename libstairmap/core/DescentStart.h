#pragma once
// The surface a descending flight starts from. A descent off the robot's floor starts at the
// floor's own edge; one whose first edge lies below the floor (the floor's nosing unseen, or a
// landing one or more steps down) has level surfaces in front of that edge: the tread or landing
// at the edge's height and, nearer the robot, steps a whole number of rises higher. A ramp down
// seen from its top by a LiDAR's rings reads as such a flight (its ring lines a few centimetres
// lower one after another: dev negatives 22022 r0092 and r0928, 5005 r0759), but in front of its
// first "edge" lies the ramp itself, at every height between that edge and the floor.

#include "core/PointCloud.h"
#include "core/Staircase.h"

namespace stairmap {

struct DescentStartParams {
    /// [m] only flights whose first edge lies at least this far below the floor are asked (in
    /// front of one on the floor lies the floor)
    double min_below_floor_m = 0.05;
    /// [m] window in front of the first edge, towards the robot: past the edge's own points ...
    double from_m = 0.03;
    double to_m = 0.6;  ///< [m] ... up to this far (two runs or more)
    /// [0..1] the ends of the first edge (this fraction of its length each) are left out: walls
    double end_fraction = 0.15;
    /// [m] the window's heights: from this far below the first edge to this far above the floor
    double z_margin_m = 0.03;
    /// [-] a point lies on a level when within this many rises of the first edge's height plus a
    /// whole number of rises (0.3: 3-6 cm, several times the dev sets' range noise there)
    double level_band_rises = 0.3;
    int min_points = 20;  ///< [-] fewer points in the window: no verdict (false)
    /// [0..1] more of the window's points off every level than this: a ramp. Found descents on
    /// the three dev sets read 0-0.04, the three ramps 0.36-0.73.
    double max_off_level_fraction = 0.2;
};

/// Whether descending flight `s` (robot frame, geometry estimated; `floor_z` the robot's floor)
/// starts on a slope: its first edge lies min_below_floor_m or more below the floor, and more than
/// max_off_level_fraction of the points in the window in front of that edge lie off the levels
/// (first edge + k rises). False for ascending flights, flights of fewer than two steps, and
/// windows with fewer than min_points points. Non-finite points are ignored. Cost: one pass over
/// the cloud.
bool descentStartsOnASlope(const PointCloud& cloud, const Staircase& s, double floor_z,
                           const DescentStartParams& params = {});

}  // namespace stairmap
