#include "core/LongTreads.h"

#include <algorithm>
#include <cmath>

namespace stairmap {
namespace {

/// Whether the tread between `lower` and `upper` is seen level (treadsSeenLevel, one tread).
bool treadSeenLevel(const PointCloud& cloud, const LineSegment& lower, const LineSegment& upper,
                    const LevelTreadParams& p) {
    const Eigen::Vector2d up = upper.normalAwayFrom(lower.centre());
    const double run = up.dot(upper.centre() - lower.centre());
    if (run <= 0.0) return false;
    const Eigen::Vector2d c = lower.centre();
    const Eigen::Vector2d u = lower.direction();
    const double half =
        0.5 * std::min(lower.length(), upper.length()) * (1.0 - 2.0 * p.end_fraction);
    const double s_lo = p.from_run * run, s_hi = p.to_run * run;
    int on = 0, between = 0;
    double t_min = 1e9, t_max = -1e9;
    for (const Eigen::Vector3f& q : cloud) {
        if (!q.allFinite()) continue;
        const Eigen::Vector2d d(q.x() - c.x(), q.y() - c.y());
        const double s = up.dot(d), t = u.dot(d);
        if (s < s_lo || s > s_hi || std::abs(t) > half) continue;
        if (std::abs(q.z() - lower.z) <= p.tread_dz_m) {
            ++on;
            t_min = std::min(t_min, t);
            t_max = std::max(t_max, t);
        } else if (q.z() > lower.z + p.tread_dz_m && q.z() < upper.z + p.above_upper_m) {
            ++between;  // a skipped step's tread, or the next step already within the window
        }
    }
    return on >= p.min_points && between <= p.max_between_fraction * on &&
           t_max - t_min >= p.min_spread_fraction * 2.0 * half &&
           on >= p.min_points_per_m2 * (s_hi - s_lo) * 2.0 * half;
}

}  // namespace

bool treadsSeenLevel(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                     const LevelTreadParams& p) {
    if (edges.size() < 2) return false;
    for (std::size_t i = 1; i < edges.size(); ++i)
        if (!treadSeenLevel(cloud, edges[i - 1], edges[i], p)) return false;
    return true;
}

double meanRun(const std::vector<LineSegment>& edges) {
    const LineSegment& first = edges.front();
    const LineSegment& last = edges.back();
    const Eigen::Vector2d up = last.normalAwayFrom(first.centre());
    return up.dot(last.centre() - first.centre()) / static_cast<double>(edges.size() - 1);
}

}  // namespace stairmap
