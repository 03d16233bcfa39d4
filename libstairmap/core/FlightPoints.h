#pragma once
// The points of a cloud around one flight's edges: the crop that the sparse-cloud corrections
// (TreadHeights, RayClearance) search instead of the whole cloud.

#include <vector>

#include "core/LineSegment.h"
#include "core/PointCloud.h"

namespace stairmap {

/// Points of `cloud` inside the XY bounding box of `edges` grown by `margin_m` on every side, with
/// z in [z_lo, z_hi] [m]. Non-finite points are dropped. One pass over the cloud.
PointCloud pointsNearEdges(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                           double margin_m, double z_lo, double z_hi);

}  // namespace stairmap
