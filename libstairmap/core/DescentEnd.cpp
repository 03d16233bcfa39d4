#include "core/DescentEnd.h"

#include <algorithm>
#include <cmath>

namespace stairmap {
namespace {

/// Points of `cloud` beyond `last` (on the side away from `above`, beyond_from..beyond_to from its
/// line, along its middle), at any height.
int pointsBeyond(const PointCloud& cloud, const LineSegment& last, const LineSegment& above,
                 const DescentEndParams& p) {
    const Eigen::Vector2d u = last.direction(), c = last.centre();
    Eigen::Vector2d n(-u.y(), u.x());
    if (n.dot(c - above.centre()) < 0.0) n = -n;  // away from the edge above
    const double half = 0.5 * last.length() * (1.0 - 2.0 * p.end_fraction);
    int beyond = 0;
    for (const Eigen::Vector3f& q : cloud) {
        const Eigen::Vector2d d(q.x() - c.x(), q.y() - c.y());
        const double s = n.dot(d);
        if (s >= p.beyond_from_m && s <= p.beyond_to_m && std::abs(u.dot(d)) <= half &&
            std::isfinite(q.z()))
            ++beyond;
    }
    return beyond;
}

}  // namespace

bool dropCropLineEnd(const PointCloud& cloud, std::vector<LineSegment>& edges,
                     const DescentEndParams& params) {
    if (edges.size() < 2) return false;
    double longest_other = 0.0;
    for (std::size_t k = 0; k + 1 < edges.size(); ++k)
        longest_other = std::max(longest_other, edges[k].length());
    if (edges.back().length() <= params.max_length_ratio * longest_other) return false;
    if (pointsBeyond(cloud, edges.back(), edges[edges.size() - 2], params) >
        params.max_points_beyond)
        return false;
    edges.pop_back();
    return true;
}

}  // namespace stairmap
