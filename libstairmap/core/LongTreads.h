#pragma once
// Flights with deep treads (outdoor and entrance stairs: the real ANYmal entrance's treads read
// 0.44-0.64 m, depending on its unknown cell size) exceed condition 2's run bound (0.45 m), and
// widening the bound for every chain lets chains through every other nosing of shallow flights
// pass (dev: rise / run MAE 0.26 / 0.50 -> 0.33 / 0.64 cm with 0.55 m). A chain with runs beyond
// the bound counts only where the cloud shows each of its treads level: between two edges of such
// a chain the skipped nosing's tread lies half-way up, and a real deep tread is flat.

#include <vector>

#include "core/LineSegment.h"
#include "core/PointCloud.h"

namespace stairmap {

struct LevelTreadParams {
    double tread_dz_m = 0.03;  ///< [m] a point is on a tread within this of its lower edge's height
    /// [0..1] the window on each tread, in fractions of its run beyond the lower edge: away from
    /// both risers (a riser's foot and the next nosing's scatter)
    double from_run = 0.25;
    double to_run = 0.75;
    double end_fraction = 0.15;  ///< [0..1] of the shorter edge's length left out at each end
    int min_points = 4;          ///< [-] fewest points on each tread's window
    /// [0..1] the tread's points must spread over at least this fraction of the window's width
    double min_spread_fraction = 0.2;
    /// [-] points above the tread up to the upper edge's height (a skipped step's tread half-way
    /// up, or the next step's when the found edges are not its nosings: a chain of lines 1.7 runs
    /// apart on an open-riser flight, dev r0043) at most this fraction of the points on the tread
    double max_between_fraction = 0.25;
    /// [m] ... counting those up to this above the upper edge's height
    double above_upper_m = 0.08;
    /// [1/m^2] and at least this many points per square metre of the window: 0 accepts a tread
    /// seen by one ring; 400 (one per 5 cm cell) asks for a tread seen densely (an elevation map,
    /// a near depth camera), where an empty patch beside it means nothing was there to be seen
    /// (a level LiDAR's rings graze a platform 5 m away and may all miss it: dev2 r0167)
    double min_points_per_m2 = 0.0;
};

/// Whether the cloud shows every tread of `edges` (a chain from the floor outward, z measured up
/// the flight; at least 2 edges) level: in each window, enough points at the lower edge's height
/// spread across it, and hardly any above it up to the upper edge's height. A tread not
/// seen at all fails. Non-finite points are ignored. Cost: one pass over the cloud per tread.
bool treadsSeenLevel(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                     const LevelTreadParams& params = {});

/// The chain's mean run [m]: the last edge's perpendicular distance from the first over the
/// number of treads, measured along the last edge's normal. Precondition: at least 2 edges.
double meanRun(const std::vector<LineSegment>& edges);

}  // namespace stairmap
