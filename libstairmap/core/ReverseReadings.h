#pragma once
// One flight's nosings read both ways. A flight rising out of a pit in front of the robot (its
// foot steps below the robot's floor, its top above) shows the same nosings as an ascending
// chain (away from the robot) and, where its treads near the robot's floor are seen from above
// and the pit's floor beyond them from the side, as a descending one heading back towards the
// robot (dev5 r0284, r0514: the flight's lower three or four nosings, each within a few cm of the
// ascending flight's, 180 deg turned). One staircase, two detections: the reading with more steps
// is kept (Algorithm 1 keeps the longest chain), the descending one on a tie.

#include <vector>

#include "core/Staircase.h"

namespace stairmap {

struct ReverseReadingParams {
    /// [-] two flights of opposite directions are one flight read both ways when at least this
    /// many edges of the shorter ...
    int min_shared_edges = 2;
    /// [-] ... and at least this fraction of them are the same stair edge as one of the other's
    /// (Definition 2, MergeParams defaults)
    double min_shared_fraction = 0.5;
};

/// Drops from `flights` (robot frame, geometry estimated) the weaker reading of every ascending /
/// descending pair that shares its edges as described above. Returns how many were dropped.
/// O(n^2 k^2) for n flights of k steps.
int dropReverseReadings(std::vector<Staircase>& flights, const ReverseReadingParams& params = {});

}  // namespace stairmap
