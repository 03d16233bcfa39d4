#pragma once
// A two-floor building with two straight staircases and a corridor (the mapping datasets' world).
//
// Layout (world frame, metres; floor 0 at z = 0, floor 1 at z = floor_height_m):
//   footprint x 0..24, y 0..10, outer walls 0.2 thick, two floors high.
//   stair_a: along the south wall (y 0.2..1.4), foot at x = 2.0, ascending towards +x.
//   stair_b: along the north wall (y 8.6..9.8), foot at x = 22.0, ascending towards -x (its run
//            may differ: stair_b_run_m).
//   floor 0: west hall x < 8, east hall x > 16, joined by a corridor y 4..6 (walls at y = 4, 6).
//   floor 1: the same halls joined by a wider corridor y 3..7; stairwell openings above each flight.

#include "sim/Scene.h"

namespace stairmap::sim {

struct BuildingParams {
    double floor_height_m = 3.0;  ///< [m] height of floor 1 (= num_risers * rise)
    int num_risers = 16;          ///< per staircase
    double run_m = 0.28;          ///< [m]
    double width_m = 1.2;         ///< [m] (the stairwell is laid out for <= 1.2 m)
    /// [m] run of stair_b; 0 = run_m. With equal runs the building is symmetric under a 180 deg
    /// turn about its centre (stair_a maps onto stair_b), so two maps that both hold both flights
    /// cannot be aligned unambiguously; a different run tells the flights apart.
    double stair_b_run_m = 0.0;
    bool furniture = true;        ///< a few tables/cabinets in the halls
};

/// Throws std::invalid_argument naming the field if a parameter is out of range.
void validate(const BuildingParams& params);

/// Adds the building; truth gets stair_a, stair_b and floor heights {0, floor_height_m}.
void addTwoFloorBuilding(Scene& scene, const BuildingParams& params);

}  // namespace stairmap::sim
