#pragma once
// A sparse LiDAR seldom hits the nosing of a step above its own height: its beams hit the riser
// below it, and the top view keeps that hit as the column's highest point. Such a riser line lies
// vertically under the real nosing line (same XY, lower z) and would pass Algorithm 1's rise test
// with the wrong height. When the nosing above it was seen too, the lower line is dropped.

#include <utility>
#include <vector>

#include "core/LineSegment.h"

namespace stairmap {

struct RiserHitParams {
    double max_offset_xy_m = 0.05;  ///< [m] the line lies this close under the higher line (across)
    double min_dz_m = 0.02;         ///< [m] ...at least this much lower
    double max_dz_m = 0.30;         ///< [m] ...and at most one rise lower
    double min_cover = 0.5;         ///< [-] the higher line spans this fraction of the lower one
};

/// Removes the lines that lie under a higher line as described above. `lines` in any order;
/// the order of the kept lines is preserved. O(n^2) in the number of lines (tens to hundreds).
void dropRiserHits(std::vector<LineSegment>& lines, const RiserHitParams& params);

/// Least-squares line z = a + b * index through (index, z) samples of a flight's edges; false
/// with fewer than two distinct indices.
bool fitHeightLine(const std::vector<std::pair<double, double>>& samples, double& a, double& b);

/// When the nosing above a riser hit was not seen, the hit itself may become an edge of a flight
/// (Algorithm 1 allows DetectorParams::edge_height_tolerance_m). Nosings lie on a straight line
/// against the step index and riser hits only ever read low, so: fit z = a + b * index to the
/// edges (ordered, consecutive steps), set aside those more than `min_drop_m` below the fit, refit,
/// until none is set aside; the set-aside edges are raised onto the final fit. Nothing changes when
/// fewer than 3 edges (or fewer than half) would remain. Returns how many edges were raised.
int raiseLowEdges(std::vector<LineSegment>& edges, double min_drop_m);

}  // namespace stairmap
