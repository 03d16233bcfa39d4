#pragma once
// The edge-level parts of the paper's merge (Sec. III-E): Definition 2 ("same stair") and
// merge(l_i, l_j) of Algorithm 2, the covariance-weighted fusion of two observations of one edge.

#include "core/MergeParams.h"
#include "core/Staircase.h"

namespace stairmap {

/// Definition 2 on two edges in the same frame: heights within params.max_height_diff_m, the
/// perpendicular XY distance between the lines within params.max_distance_m, orientations within
/// params.max_angle_deg, plus the overlap gate params.min_edge_overlap_m along the edge.
bool isSameStairEdge(const StairEdge& a, const StairEdge& b, const MergeParams& params = {});

/// Fuses two observations of the same edge, weighted by `weight_a` / `weight_b` observations.
/// - Line: (rho, theta) fused in information form about a's centre. Each edge's uncertainty is the
///   origin-independent part of its cov_rho_theta: var(rho | theta) (perpendicular variance at the
///   fit centroid, taken as the edge centre) and var(theta), floored by params.min_sigma_*.
/// - Height: inverse perpendicular-variance weighted mean.
/// - Extent along the fused line: ends within params.endpoint_tolerance_m are averaged by weight,
///   an end farther out extends the edge (a partial view never shortens it).
/// `heading_rad` is the staircase heading the result follows: start is the left end when facing
/// it (core/Staircase.h). The result's cov_rho_theta is about the frame origin (rho >= 0
/// convention) and num_points add up. Cost O(1).
StairEdge fuseEdges(const StairEdge& a, int weight_a, const StairEdge& b, int weight_b,
                    double heading_rad, const MergeParams& params = {});

}  // namespace stairmap
