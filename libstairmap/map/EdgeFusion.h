#pragma once
// Covariance-weighted fusion of two observations of the same step edge (the "merge(l_i, l_j)" of
// the paper's Algorithm 2, using the line covariance of the weighted line fit).

#include "core/Staircase.h"
#include "map/LandmarkParams.h"

namespace stairmap {

/// Fuses two edges of the same stair in the world frame, weighted by `weight_a`/`weight_b`
/// observations for the end points. The supporting lines are fused in information form in
/// (rho, theta) about a local origin; each edge's uncertainty is taken from its cov_rho_theta as
/// the origin-independent part: var(rho | theta) (the perpendicular variance at the fit centroid,
/// taken as the edge centre) and var(theta). End points: ends within
/// params.endpoint_tolerance_m are averaged, an end farther out extends the edge (partial views).
/// Height: inverse-variance weighted. The result's cov_rho_theta is about the world origin in the
/// rho >= 0 convention of core/Staircase.h; start is the left end when facing uphill.
StairEdge fuseEdges(const StairEdge& a, int weight_a, const StairEdge& b, int weight_b,
                    double uphill_rad, const LandmarkParams& params);

}  // namespace stairmap
