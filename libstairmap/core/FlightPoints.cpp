#include "core/FlightPoints.h"

#include <limits>

namespace stairmap {

FlightBox flightBox(const std::vector<LineSegment>& edges, double margin_m, double z_lo,
                    double z_hi) {
    FlightBox box;
    box.lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    box.hi = -box.lo;
    for (const LineSegment& e : edges) {
        box.lo = box.lo.cwiseMin(e.start).cwiseMin(e.end);
        box.hi = box.hi.cwiseMax(e.start).cwiseMax(e.end);
    }
    box.lo.array() -= margin_m;
    box.hi.array() += margin_m;
    box.z_lo = z_lo;
    box.z_hi = z_hi;
    return box;
}

PointCloud pointsInBox(const PointCloud& cloud, const FlightBox& box) {
    PointCloud out;
    for (const Eigen::Vector3f& q : cloud)
        if (box.contains(q)) out.push_back(q);
    return out;
}

PointCloud pointsNearEdges(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                           double margin_m, double z_lo, double z_hi) {
    return pointsInBox(cloud, flightBox(edges, margin_m, z_lo, z_hi));
}

}  // namespace stairmap
