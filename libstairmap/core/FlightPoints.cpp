#include "core/FlightPoints.h"

#include <limits>

namespace stairmap {

PointCloud pointsNearEdges(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                           double margin_m, double z_lo, double z_hi) {
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector2d hi = -lo;
    for (const LineSegment& e : edges) {
        lo = lo.cwiseMin(e.start).cwiseMin(e.end);
        hi = hi.cwiseMax(e.start).cwiseMax(e.end);
    }
    lo.array() -= margin_m;
    hi.array() += margin_m;
    PointCloud out;
    for (const Eigen::Vector3f& q : cloud) {  // NaN fails every comparison: dropped
        if (q.x() >= lo.x() && q.x() <= hi.x() && q.y() >= lo.y() && q.y() <= hi.y() &&
            q.z() >= z_lo && q.z() <= z_hi)
            out.push_back(q);
    }
    return out;
}

}  // namespace stairmap
