#pragma once
// Straight ascending flights read from their profile (issue 10). Algorithm 1 chains a flight edge
// by edge: each pair must overlap laterally (condition 4) and lie one rise and one run apart. A
// far level LiDAR breaks that in two ways at once: its rings alias with the steps (lines on every
// other nosing, pairs two runs apart) and each nosing's line is a 0.2-0.4 m piece at its own place
// along the nosing (a ring crossing an open-riser flight obliquely), so consecutive pieces do not
// overlap (dev3 r0247: an HDL-32 5.9 m from a 16-step flight, lines on 10 of its nosings, no pair
// chained). Seen across the flight instead, the pieces' distances up the flight and their heights
// lie on one comb: the k-th step's nosing k runs and k rises from the first. This search looks for
// such combs among parallel lines, whatever their lateral places, and returns them as chains with
// the steps they skip put back.

#include <vector>

#include "core/LineSegment.h"

namespace stairmap {

struct ProfileChainParams {
    double floor_z = 0.0;             ///< [m] the robot's floor
    double min_rise_m = 0.10;         ///< [m] condition 1 (DetectorParams::min_step_height_m)
    double max_rise_m = 0.22;         ///< [m] (max_step_height_m)
    double min_run_m = 0.15;          ///< [m] condition 2 (min_step_depth_m)
    double max_run_m = 0.45;          ///< [m] (max_step_depth_m)
    double min_seed_length_m = 0.25;  ///< [m] a comb is looked for about lines this long
    double max_turn_deg = 15.0;       ///< [deg] members parallel to the seed within this
    /// [m] members' extents lie within this of the seed's across the flight (a flight's width)
    double max_lateral_m = 2.5;
    /// [-] a member lies within this fraction of a run (and at least 4 cm) of its comb tooth, up
    /// the flight: lines stand on the nosings or the risers under them
    double spacing_tolerance = 0.2;
    /// [m] a member's height may lie this much below its tooth's (riser hits of far rings read
    /// low) ...
    double below_tolerance_m = 0.05;
    double above_tolerance_m = 0.025;  ///< [m] ... and this much above it
    int max_multiple = 3;              ///< [-] a seed pair may lie up to this many steps apart
    int min_seen_steps = 5;            ///< [-] distinct teeth holding a line
    int max_gap_steps = 1;             ///< [-] consecutive teeth without a line, at most
    /// [-] the first tooth lies a whole number of rises (1 .. this) above the floor, within
    /// floor_tolerance_rises of one: the steps below it are put back
    int max_first_step = 3;
    double floor_tolerance_rises = 0.3;
};

/// The combs among `lines` (real z, one kind of nosing: front drops, the flight rising away from
/// the origin), seeds taken longest first, each as edges from the floor outward. A seen tooth's
/// edge lies on the comb (the nosings' mean direction, its distance up the flight) across its
/// members' lateral extent, at its longest member's height, with that member's points; a tooth
/// without a line is put back halfway between its neighbours, and the teeth between the floor and
/// the first seen one one run and one rise apart (unseenNosing: num_points 0). A line belongs to
/// one comb at most. Cost: per seed, a pass over the lines, then its pairs with the parallel
/// lines within max_multiple runs, each scored over those lines.
std::vector<std::vector<LineSegment>> findProfileChains(const std::vector<LineSegment>& lines,
                                                        const ProfileChainParams& params = {});

}  // namespace stairmap
