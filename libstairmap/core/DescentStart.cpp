#include "core/DescentStart.h"

#include <algorithm>
#include <cmath>

#include "core/FlightPoints.h"

namespace stairmap {

bool descentStartsOnASlope(const PointCloud& cloud, const Staircase& s, double floor_z,
                           const DescentStartParams& p) {
    if (s.direction != StairDirection::Descending || s.steps.size() < 2) return false;
    const StairEdge& first = s.steps.front();
    const double z0 = first.start.z(), rise = s.step_height;
    if (!(rise > 0) || z0 > floor_z - p.min_below_floor_m) return false;
    const Eigen::Vector2d a = first.start.head<2>(), b = first.end.head<2>();
    const double length = (b - a).norm();
    if (!(length > 0)) return false;
    const Eigen::Vector2d along = (b - a) / length, centre = first.centre().head<2>();
    Eigen::Vector2d out(-along.y(), along.x());  // across the edge, down the flight
    const Eigen::Vector2d heading(std::cos(s.heading_rad), std::sin(s.heading_rad));
    if (out.dot(heading) < 0) out = -out;
    const double half = 0.5 * length * (1.0 - 2.0 * p.end_fraction);
    // A box around the window: most of the cloud fails its comparisons.
    FlightBox box{centre, centre, z0 - p.z_margin_m, floor_z + p.z_margin_m};
    for (const double d : {-p.to_m, -p.from_m})
        for (const double t : {-half, half}) {
            const Eigen::Vector2d q = centre + d * out + t * along;
            box.lo = box.lo.cwiseMin(q);
            box.hi = box.hi.cwiseMax(q);
        }
    int inside = 0, off_level = 0;
    for (const Eigen::Vector3f& q : cloud) {
        if (!box.contains(q)) continue;  // also non-finite points
        const Eigen::Vector2d d(q.x() - centre.x(), q.y() - centre.y());
        const double across = out.dot(d);
        if (across < -p.to_m || across > -p.from_m || std::abs(along.dot(d)) > half) continue;
        const double levels = (q.z() - z0) / rise;
        ++inside;
        if (std::abs(levels - std::round(levels)) > p.level_band_rises) ++off_level;
    }
    return inside >= p.min_points && off_level > p.max_off_level_fraction * inside;
}

}  // namespace stairmap
