#include "core/NosingSlope.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace stairmap {

std::optional<double> slopeAlongNosings(const PointCloud& cloud,
                                        const std::vector<LineSegment>& edges,
                                        const NosingSlopeParams& params) {
    if (edges.size() < 2) return std::nullopt;
    const LineSegment& first = edges.front();
    const LineSegment& last = edges.back();
    const Eigen::Vector2d u = first.direction();
    const Eigen::Vector2d n = first.normalAwayFrom(Eigen::Vector2d::Zero());
    const Eigen::Vector2d origin = first.centre();
    const double s_hi = n.dot(last.centre() - origin);
    if (s_hi <= 0) return std::nullopt;
    double t_lo = std::numeric_limits<double>::infinity(), t_hi = -t_lo;
    for (const LineSegment& e : edges) {
        for (const Eigen::Vector2d& end : {e.start, e.end}) {
            t_lo = std::min(t_lo, u.dot(end - origin));
            t_hi = std::max(t_hi, u.dot(end - origin));
        }
    }
    const double rise = (last.z - first.z) / static_cast<double>(edges.size() - 1);
    const double z_lo = first.z - std::abs(rise), z_hi = last.z + std::abs(rise);
    // Points under the flight, centred on the box for conditioning.
    std::vector<Eigen::Vector3d> points;  // (s, t, z)
    const double s_mid = 0.5 * s_hi, t_mid = 0.5 * (t_lo + t_hi);
    for (const Eigen::Vector3f& q : cloud) {
        if (!q.allFinite() || q.z() < z_lo || q.z() > z_hi) continue;
        const Eigen::Vector2d d = q.head<2>().cast<double>() - origin;
        const double s = n.dot(d), t = u.dot(d);
        if (s < 0 || s > s_hi || t < t_lo || t > t_hi) continue;
        points.emplace_back(s - s_mid, t - t_mid, q.z());
    }
    // z = a + b s + c t by least squares, refitted on the points within inlier_rises of a rise
    // of the plane: a stair's profile lies within half a rise of it, a wall or a box beside or
    // on the treads does not.
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    bool fitted = false;
    for (int fit = 0; fit <= params.refits; ++fit) {
        Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
        Eigen::Vector3d atz = Eigen::Vector3d::Zero();
        int count = 0;
        double seen_lo = std::numeric_limits<double>::infinity(), seen_hi = -seen_lo;
        for (const Eigen::Vector3d& q : points) {
            const Eigen::Vector3d row(1.0, q.x(), q.y());
            if (fitted && std::abs(q.z() - row.dot(x)) > params.inlier_rises * std::abs(rise))
                continue;
            ata += row * row.transpose();
            atz += row * q.z();
            ++count;
            seen_lo = std::min(seen_lo, q.y());
            seen_hi = std::max(seen_hi, q.y());
        }
        if (count < params.min_points || seen_hi - seen_lo < params.min_spread_m)
            return std::nullopt;
        x = ata.ldlt().solve(atz);
        if (!x.allFinite()) return std::nullopt;
        fitted = true;
    }
    return x.z();
}

}  // namespace stairmap
