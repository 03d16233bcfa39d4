#pragma once
// One spiral found as two turning flights (issue 10). Algorithm 1's chains through a spiral stop
// where a level is missed or read off, and the chain through its upper levels stands as a second
// flight on the same spiral: a false positive beside the found one (an elevation map 2.4 m from a
// 12-level spiral gives levels 0-4 and 5-10 as two chains; a pitched OS1-64 6.6 m from a 16-level
// one levels 0-4 and 5-14). Both pieces turn about one axis (TurningFlight: 2-17 cm apart) with one
// step angle and rise, and the upper piece's first level continues the lower one's helix: one step
// (or two, a level put back between) higher and turned by as many step angles. Such pieces are
// joined into one flight.

#include <vector>

#include "core/Staircase.h"

namespace stairmap {

struct SpiralPieceParams {
    double max_axis_distance_m = 0.20;   ///< [m] the two pieces' axes lie this close
    double max_rise_diff_m = 0.03;       ///< [m] their rises agree within this
    double max_step_angle_ratio = 1.35;  ///< [-] larger / smaller step angle at most this
    /// [-] the gap between the lower piece's last level and the upper's first, in rises, may be off
    /// a whole number of steps (1 or 2) by this fraction of a rise (check4 r0292: 1.36 rises, the
    /// lower piece's rise read 0.112 m on a 0.129 m spiral) ...
    double level_tolerance = 0.4;
    /// [-] ... and the upper's first edge's angle about the axis off the helix by this fraction of
    /// a step angle
    double angle_tolerance = 0.5;
};

/// Joins ascending turning flights of `flights` that are pieces of one spiral (the put-back level
/// between two steps apart is halfway between its neighbours). Returns how many were joined away.
/// O(n^2 k) for n flights of k steps.
int joinSpiralPieces(std::vector<Staircase>& flights, const SpiralPieceParams& params = {});

/// Drops the ascending turning flights that lie on one spiral with a flight starting lower (same
/// axis, turn and step angle as joinSpiralPieces asks) but do not continue its helix: a level
/// LiDAR sees a spiral's levels above its own height only by riser hits, whose lines lie at the
/// rings' heights, 2-19 cm below the nosings they belong to (dev2 r0066: levels 0-4 found right,
/// levels 6-13 read as a second flight starting 0.06 m above the first one's top). One spiral is
/// one flight; the lowest piece holds its foot. Returns how many were dropped. O(n^2 k).
int dropSpiralRepeats(std::vector<Staircase>& flights, const SpiralPieceParams& params = {});

}  // namespace stairmap
