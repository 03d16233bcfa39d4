#pragma once
// Fusing lines that are one physical edge: the same nosing split over two neighbouring z rows by
// noise, or interrupted by debris in one row. Without this, duplicates would count as
// "a line in between" (Definition 1, condition 5) and halve the support of each edge.

#include <vector>

#include "core/LineSegment.h"

namespace stairmap {

struct LineFusionParams {
    double max_dz_m = 0.06;         ///< [m] height difference of fusable lines
    double max_distance_m = 0.04;   ///< [m] perpendicular XY distance
    double max_angle_deg = 5.0;     ///< [deg]
    double max_gap_m = 0.40;        ///< [m] gap between the extents along the line
};

/// Information-weighted fusion of two lines: (rho, theta) fused with their covariances, extent =
/// union of both along the fused line, z = support-weighted mean.
LineSegment fuseLines(const LineSegment& a, const LineSegment& b);

/// Sorts `lines` by z and greedily fuses compatible lines. Cost O(n * k), k = lines within max_dz.
void fuseDuplicateLines(std::vector<LineSegment>& lines, const LineFusionParams& params);

/// Interval of the segment's end points projected on unit direction u.
std::pair<double, double> extentAlong(const LineSegment& s, const Eigen::Vector2d& u);

/// Smallest angle between the two (undirected) lines [rad].
double lineAngle(const LineSegment& a, const LineSegment& b);

}  // namespace stairmap
