#include "core/FlightPoints.h"

#include <algorithm>
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

FloatBounds floatBounds(const FlightBox& a, const FlightBox& b) {
    constexpr double kPad = 0.01;  // [m]
    const auto lower = [](double u, double v) { return static_cast<float>(std::min(u, v) - kPad); };
    const auto upper = [](double u, double v) { return static_cast<float>(std::max(u, v) + kPad); };
    return {{lower(a.lo.x(), b.lo.x()), lower(a.lo.y(), b.lo.y()), lower(a.z_lo, b.z_lo)},
            {upper(a.hi.x(), b.hi.x()), upper(a.hi.y(), b.hi.y()), upper(a.z_hi, b.z_hi)}};
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
