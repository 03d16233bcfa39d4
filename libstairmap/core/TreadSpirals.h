#pragma once
// Spirals read from their treads (issue 10). The spiral search (SpiralSearch) finds a spiral by
// the radial row lines on its nosings; where a view shows the wedge treads well but the row lines
// miss the nosings seen along the line of sight (a depth camera over a spiral's foot, dev6 r0718),
// the search often still glimpses the axis through three levels (SpiralGlimpse). About that axis
// a coarse top surface is filled from the cloud, its tread boundaries are read as nosings
// (TreadBoundaries), and the search runs once more on them with the row lines near the axis,
// through pairs that hold a tread nosing (SpiralSearchParams::pair_lines), four seen levels
// enough, two of them on tread nosings.

#include <vector>

#include "core/LineSegment.h"
#include "core/PointCloud.h"
#include "core/SpiralSearch.h"

namespace stairmap {

struct TreadSpiralParams {
    double cell_m = 0.05;   ///< [m] the surface's cells (DetectorParams::tread_spiral_cell_m)
    double window_m = 3.0;  ///< [m] its half size about the axis (tread_spiral_window_m)
    double max_height_above_floor_m = 3.0;  ///< [m] points higher are left out (as the top view)
};

/// The spirals about `axis` (robot frame, the glimpse of the first search on `front_drops` and
/// `back_drops`) whose seen levels include two tread nosings; `search` as for that first search
/// (its floor, rises, runs). Cost: one pass over the cloud, one over the surface's
/// (2 window_m / cell_m + 2)^2 cells, and the spiral search on the tread nosings with the row
/// lines that have an end within the window.
std::vector<SpiralFlight> findTreadSpirals(const PointCloud& cloud, const Eigen::Vector2d& axis,
                                           const std::vector<LineSegment>& front_drops,
                                           const std::vector<LineSegment>& back_drops,
                                           const SpiralSearchParams& search,
                                           const TreadSpiralParams& params = {});

}  // namespace stairmap
