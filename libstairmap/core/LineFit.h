#pragma once
// Weighted least-squares line fit in the plane with the covariance of the Hessian parameters
// (rho, theta), as used by the paper's segmentation (Sec. III-B, after Pfister et al.).

#include <Eigen/Core>
#include <cstddef>

#include "core/LineSegment.h"

namespace stairmap {

/// Points given as an array of XY positions (and heights, averaged into z).
struct RowPointView {
    const float* x;
    const float* y;
    const float* z;
};

/// Fits the total-least-squares line to points [first, last] (inclusive) of `pts`, all with standard
/// deviation sigma [m] (weights 1/sigma^2; the residual spread is used when larger). The segment's
/// end points are the projections of the first and last point on the line, so no end point is lost.
/// Covariance: var(theta) = s2 / sum(t_i^2), var(rho at centroid) = s2 / n, propagated to rho at
/// the origin with d rho / d theta = centroid . n'(theta). Cost O(n).
LineSegment fitLine(const RowPointView& pts, std::size_t first, std::size_t last, double sigma);

/// Mahalanobis distance^2 of the (rho, theta) difference of two lines under cov_a + cov_b.
double lineMahalanobis2(const LineSegment& a, const LineSegment& b);

}  // namespace stairmap
