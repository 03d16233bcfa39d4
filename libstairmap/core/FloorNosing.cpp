#include "core/FloorNosing.h"

#include <algorithm>
#include <cmath>

namespace stairmap {

std::optional<LineSegment> measureFloorNosing(const std::vector<TopViewCell>& cells,
                                              const LineSegment& first, const Eigen::Vector2d& heading,
                                              double run, const FloorNosingParams& p) {
    // The flight's mean direction, not the first lower nosing's own: that edge is often seen only in
    // part and its fitted direction tilted by a few degrees, which would shift the floor edge.
    const Eigen::Vector2d n = heading.normalized();  // normal pointing down the flight
    const Eigen::Vector2d u(-n.y(), n.x());
    const Eigen::Vector2d anchor = first.centre() - run * n;  // predicted floor nosing centre
    const double a = u.dot(first.start - anchor), b = u.dot(first.end - anchor);
    const double lo = std::min(a, b), hi = std::max(a, b);
    std::vector<double> offsets;
    std::vector<float> heights;
    for (const auto& c : cells) {
        if (!(c.flags & kBackDrop) || std::abs(c.z - p.floor_z) > p.z_tolerance_m) continue;
        const Eigen::Vector2d d(c.x - anchor.x(), c.y - anchor.y());
        const double along = u.dot(d), across = n.dot(d);
        if (along < lo || along > hi || std::abs(across) > p.search_band_m) continue;
        offsets.push_back(across);
        heights.push_back(c.z);
    }
    if (static_cast<int>(offsets.size()) < p.min_points) return std::nullopt;
    std::vector<double> sorted = offsets;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double median = sorted[sorted.size() / 2];
    double sum = 0.0, zsum = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < offsets.size(); ++i) {
        if (std::abs(offsets[i] - median) > p.inlier_band_m) continue;
        sum += offsets[i];
        zsum += heights[i];
        ++count;
    }
    if (count < p.min_points) return std::nullopt;
    const Eigen::Vector2d centre = anchor + (sum / count) * n;
    LineSegment out = first;
    out.start = centre + lo * u;
    out.end = centre + hi * u;
    out.z = zsum / count;
    out.num_points = count;
    out.theta = std::atan2(n.y(), n.x());
    if (std::cos(out.theta - first.theta) < 0) out.theta = std::remainder(out.theta + M_PI, 2 * M_PI);
    out.rho = centre.dot(Eigen::Vector2d(std::cos(out.theta), std::sin(out.theta)));
    if (out.rho < 0) {  // keep rho >= 0 (flip the Hessian branch)
        out.rho = -out.rho;
        out.theta = std::remainder(out.theta + M_PI, 2 * M_PI);
        out.cov(0, 1) = -out.cov(0, 1);
        out.cov(1, 0) = -out.cov(1, 0);
    }
    // Offset measured from `count` points of noise ~sigma: scale the line's rho variance.
    out.cov(0, 0) = first.cov(0, 0) * std::max(1, first.num_points) / count;
    return out;
}

}  // namespace stairmap
