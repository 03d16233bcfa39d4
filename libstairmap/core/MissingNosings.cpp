#include "core/MissingNosings.h"

#include <algorithm>
#include <cmath>

namespace stairmap {
namespace {

constexpr double kMinGapRatio = 1.6;  ///< [-] a pair this many median rises apart has a gap ...
constexpr double kMaxGapRatio = 2.4;  ///< [-] ... up to this many
/// [m^2, rad^2] variances of an unseen edge's (rho, theta): it is a guess, worth little in merges
constexpr double kUnseenRhoVar = 0.05 * 0.05;
constexpr double kUnseenThetaVar = 0.1 * 0.1;

/// The edge halfway between a and b, its end points paired by their position along a.
LineSegment halfway(const LineSegment& a, const LineSegment& b) {
    const Eigen::Vector2d u = a.direction();
    const bool same_order = u.dot(b.end - b.start) >= 0;
    const Eigen::Vector2d b_start = same_order ? b.start : b.end;
    const Eigen::Vector2d b_end = same_order ? b.end : b.start;
    return unseenNosing(0.5 * (a.start + b_start), 0.5 * (a.end + b_end), 0.5 * (a.z + b.z));
}

}  // namespace

LineSegment unseenNosing(const Eigen::Vector2d& start, const Eigen::Vector2d& end, double z) {
    LineSegment m;
    m.start = start;
    m.end = end;
    m.z = z;
    const Eigen::Vector2d d = (end - start).normalized();
    Eigen::Vector2d n(d.y(), -d.x());
    if (n.dot(m.start) < 0) n = -n;  // Hessian form: rho >= 0
    m.rho = n.dot(m.start);
    m.theta = std::atan2(n.y(), n.x());
    m.cov << kUnseenRhoVar, 0.0, 0.0, kUnseenThetaVar;
    m.num_points = 0;
    return m;
}

int fillMissingNosings(std::vector<LineSegment>& edges) {
    if (edges.size() < 3) return 0;
    std::vector<double> rises;
    for (std::size_t i = 1; i < edges.size(); ++i)
        rises.push_back(std::abs(edges[i].z - edges[i - 1].z));
    std::nth_element(rises.begin(), rises.begin() + rises.size() / 2, rises.end());
    const double rise = rises[rises.size() / 2];
    if (rise <= 0.0) return 0;
    int inserted = 0;
    for (std::size_t i = 1; i < edges.size(); ++i) {
        const double ratio = std::abs(edges[i].z - edges[i - 1].z) / rise;
        if (ratio < kMinGapRatio || ratio > kMaxGapRatio) continue;
        edges.insert(edges.begin() + static_cast<std::ptrdiff_t>(i),
                     halfway(edges[i - 1], edges[i]));
        ++inserted;
        ++i;  // skip the inserted edge
    }
    return inserted;
}

}  // namespace stairmap
