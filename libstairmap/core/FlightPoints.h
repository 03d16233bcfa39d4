#pragma once
// The points of a cloud around one flight's edges: the crop that the sparse-cloud corrections
// (TreadHeights, RayClearance) search instead of the whole cloud.

#include <vector>

#include "core/LineSegment.h"
#include "core/PointCloud.h"

namespace stairmap {

/// The XY bounding box of a flight's edges grown by a margin, with a height band [m]. Testing a
/// point against it where the point is used costs less than copying the points inside (a dense
/// depth camera looking down at a flight has nearly all of its points there).
struct FlightBox {
    Eigen::Vector2d lo, hi;
    double z_lo = 0.0, z_hi = 0.0;
    /// Inside, borders included; a NaN coordinate fails every comparison: outside.
    bool contains(const Eigen::Vector3f& q) const {
        return q.x() >= lo.x() && q.x() <= hi.x() && q.y() >= lo.y() && q.y() <= hi.y() &&
               q.z() >= z_lo && q.z() <= z_hi;
    }
};

/// Float bounds around a region (boxes, a strip), padded by a centimetre (far more than float
/// rounding at 100 m): a point outside them lies outside the region and is rejected by float
/// comparisons alone, without converting its coordinates to double (most of a cloud); one inside
/// is then tested exactly. A NaN coordinate fails them.
struct FloatBounds {
    Eigen::Vector3f lo, hi;
    bool mayContain(const Eigen::Vector3f& q) const {
        return q.x() >= lo.x() && q.x() <= hi.x() && q.y() >= lo.y() && q.y() <= hi.y() &&
               q.z() >= lo.z() && q.z() <= hi.z();
    }
};

/// FloatBounds holding both `a` and `b`.
FloatBounds floatBounds(const FlightBox& a, const FlightBox& b);

/// The XY bounding box of `edges` grown by `margin_m` on every side, with z in [z_lo, z_hi] [m]
/// (empty when there are no edges).
FlightBox flightBox(const std::vector<LineSegment>& edges, double margin_m, double z_lo,
                    double z_hi);

/// Points of `cloud` inside `box`, in cloud order. Non-finite points are dropped. One pass.
PointCloud pointsInBox(const PointCloud& cloud, const FlightBox& box);

/// Points of `cloud` inside flightBox(edges, margin_m, z_lo, z_hi), in cloud order. Non-finite
/// points are dropped. One pass over the cloud.
PointCloud pointsNearEdges(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                           double margin_m, double z_lo, double z_hi);

}  // namespace stairmap
