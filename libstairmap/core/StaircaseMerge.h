#pragma once
// Merging two detections of the same staircase (paper Sec. III-E: Algorithm 2 with Definition 2),
// with covariance-weighted fusion of matched edges.

#include <optional>

#include "core/Staircase.h"

namespace stairmap {

/// Definition 2 ("same stair") thresholds plus the lateral gate this implementation adds.
struct MergeParams {
    double max_height_diff_m = 0.05;  ///< [m] condition 1: |z_a - z_b|
    double max_distance_m = 0.05;     ///< [m] condition 2: perpendicular XY distance of the lines
    double max_angle_deg = 10.0;      ///< [deg] condition 3: |alpha_a - alpha_b|
    /// [m] the two edges' extents along the line may be apart by at most this (0 = must overlap);
    /// keeps side-by-side flights at equal heights apart.
    double max_lateral_gap_m = 0.3;
};

/// Definition 2: are two edges (same frame) the same physical stair edge?
bool isSameStairEdge(const StairEdge& a, const StairEdge& b, const MergeParams& params = {});

/// Covariance-weighted fusion of two edges of the same line: (rho, theta) fused in information
/// form from each edge's cov_rho_theta, the extent is the union of both extents projected on the
/// fused line, z is the support-weighted mean height, num_points add up. Keeps a's start->end sense.
StairEdge fuseEdges(const StairEdge& a, const StairEdge& b);

/// Algorithm 2. Preconditions: both staircases in the same frame, with the same `direction` and the
/// same ordering convention. The mapper passes both in canonical form (toBottomUp()): Ascending,
/// steps ordered bottom to top, so that a flight seen ascending from the bottom and one seen
/// descending from the top are comparable. Works with any overlap (one common step suffices; one
/// may be a subset of the other). The step-index offset is the one with the most matching edge
/// pairs (Definition 2), not only the first match; matched edges are fused (fuseEdges), edges of only
/// one input are kept in order (prepended/appended), and the geometry is re-estimated.
/// Returns std::nullopt when no edge pair matches. Throws std::invalid_argument if the directions differ.
std::optional<Staircase> mergeStaircases(const Staircase& a, const Staircase& b,
                                         const MergeParams& params = {});

/// Canonical form for merging: a Descending staircase (steps top to bottom, heading down) becomes
/// Ascending with the steps reversed (bottom to top) and the heading turned by pi; the nosings are
/// the same physical edges. Ascending input is returned unchanged. Geometry is re-estimated.
Staircase toBottomUp(const Staircase& stairs);

}  // namespace stairmap
