#pragma once
// Plain data of the landmark map (header only, so io/ can (de)serialise it without linking map/).

#include <map>
#include <vector>

#include "core/Staircase.h"
#include "map/LandmarkParams.h"

namespace stairmap {

/// One staircase of the persistent map. `stairs` is in the WORLD frame and canonical whichever way
/// it was seen: direction Ascending, steps ordered bottom to top, every edge's `start` on the left
/// and `end` on the right when facing uphill (as core/Staircase.h), `location` = centre of the lowest edge (the nosing of
/// the first tread), `heading_rad` = uphill direction (counter-clockwise from world +x).
struct StaircaseLandmark {
    int id = -1;                      ///< stable, never reused (absorbed IDs stay retired)
    Staircase stairs;                 ///< world frame, canonical (see above)
    std::vector<int> step_observations;  ///< per step: how many detections contributed to it
    bool confirmed = false;           ///< observations >= LandmarkParams::confirm_observations
    int observations = 0;             ///< detections fused into this landmark
    double first_seen_s = 0.0;        ///< [s] stamp of the first detection
    double last_seen_s = 0.0;         ///< [s] stamp of the latest detection
    /// The flight's ends were actually seen: an ascending detection starts at the lowest nosing,
    /// a descending one at the top nosing (flush with the upper floor). Only observed ends may
    /// create floor levels, so a partially seen flight does not invent a floor at its last step.
    bool bottom_observed = false;
    bool top_observed = false;
    int bottom_floor = -1;            ///< id of the floor the flight leaves from, -1 if unknown
    int top_floor = -1;               ///< id of the floor the flight reaches, -1 if unknown
};

/// A floor level (a node of the floor graph; staircases are its edges).
struct Floor {
    int id = -1;                ///< stable, never reused
    double z = 0.0;             ///< [m] world height of the walking surface
    int robot_samples = 0;      ///< robot floor heights that fell on this level
    int staircase_ends = 0;     ///< staircase bottoms/tops attached to this level
    double robot_z_sum = 0.0;   ///< [m] sum of those robot heights (running mean, kept exactly)
    double end_z_sum = 0.0;     ///< [m] sum of the staircase end heights

    int support() const { return robot_samples + staircase_ends; }
};

/// One climb or descent of the robot between floor levels (the mapper's level guard saw it leave
/// and regain level ground). Kept in the map so that a flight detected later is linked too.
struct FloorTransit {
    /// [m] world; z is the floor under the robot (robot z minus its height). First and last are
    /// on level ground, the others were taken while climbing (subsampled, see the mapper).
    std::vector<Eigen::Vector3d> floor_path;
    double stamp_s = 0.0;  ///< [s] when the robot regained level ground
};

/// Everything needed to continue a map exactly (what the JSON document stores).
struct LandmarkMapState {
    std::vector<StaircaseLandmark> staircases;  ///< ordered by id
    std::vector<Floor> floor_levels;  ///< every height cluster, reported or not, ordered by id
    std::map<int, int> absorbed;      ///< retired landmark id -> id of the landmark it joined
    std::vector<FloorTransit> transits;  ///< the robot's climbs between floors, oldest first
    int next_landmark_id = 0;
    int next_floor_id = 0;
};

}  // namespace stairmap
