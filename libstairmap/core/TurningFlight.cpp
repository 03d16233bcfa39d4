#include "core/TurningFlight.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/StaircaseGeometry.h"

namespace stairmap {
namespace {

/// Value at fraction q of the sorted values (q = 0.5: the median).
double quantile(std::vector<double> v, double q) {
    const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1) + 0.5);
    std::nth_element(v.begin(), v.begin() + k, v.end());
    return v[static_cast<std::size_t>(k)];
}

/// The median, or of the two middle values the lower one (an even count).
double lowerMedian(std::vector<double> v) {
    const auto k = static_cast<std::ptrdiff_t>((v.size() - 1) / 2);
    std::nth_element(v.begin(), v.begin() + k, v.end());
    return v[static_cast<std::size_t>(k)];
}

/// [rad] Turn per step: the median of the angle differences per index step over all pairs of
/// seen edges (Theil-Sen; `seen[i]` false for an edge put back between seen ones, whose angle is
/// interpolated). A level whose line is its tread's back edge lies one step angle ahead of its
/// nosing and pulls a least-squares slope over every edge (dev r0230: 29 deg read for 24).
/// Falls back to the least-squares slope over all edges with fewer than two seen.
double stepAngleOfSeenEdges(const std::vector<double>& phi, const std::vector<char>& seen) {
    std::vector<double> slopes;
    for (std::size_t i = 0; i < phi.size(); ++i)
        for (std::size_t j = i + 1; j < phi.size(); ++j)
            if (seen[i] && seen[j])
                slopes.push_back((phi[j] - phi[i]) / static_cast<double>(j - i));
    if (slopes.empty()) return std::abs(slopeAgainstIndex(phi));
    return std::abs(quantile(std::move(slopes), 0.5));
}

}  // namespace

std::optional<TurningFlight> turningFlight(const Staircase& s, const TurningFlightParams& p) {
    const std::size_t n = s.steps.size();
    if (n < 3) return std::nullopt;
    // Axis: the point nearest (least squares) to every edge's line.
    Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    for (const StairEdge& e : s.steps) {
        const Eigen::Vector2d d = (e.end - e.start).head<2>();
        if (d.norm() < 1e-6) return std::nullopt;
        const Eigen::Vector2d nrm = Eigen::Vector2d(-d.y(), d.x()).normalized();
        a += nrm * nrm.transpose();
        b += nrm * nrm.dot(e.start.head<2>());
    }
    if (std::abs(a.determinant()) < 1e-6) return std::nullopt;  // parallel edges: straight
    TurningFlight t;
    t.axis = a.ldlt().solve(b);
    // Angles of the edges around it (towards their outer ends), unwrapped step by step.
    std::vector<double> phi, inner, outer;
    std::vector<char> seen;
    int radial = 0;
    for (const StairEdge& e : s.steps) {
        const Eigen::Vector2d p0 = e.start.head<2>() - t.axis, p1 = e.end.head<2>() - t.axis;
        const Eigen::Vector2d d = (p1 - p0).normalized();
        radial += std::abs(d.x() * p0.y() - d.y() * p0.x()) <= p.max_axis_offset_m;
        const Eigen::Vector2d far = p0.norm() > p1.norm() ? p0 : p1;
        double angle = std::atan2(far.y(), far.x());
        if (!phi.empty()) angle = phi.back() + std::remainder(angle - phi.back(), 2.0 * M_PI);
        phi.push_back(angle);
        seen.push_back(e.num_points > 0);
        if (e.num_points > 0) {  // seen; put-back edges are interpolated
            inner.push_back(std::min(p0.norm(), p1.norm()));
            outer.push_back(std::max(p0.norm(), p1.norm()));
        }
    }
    if (2 * radial <= static_cast<int>(n) || inner.empty()) return std::nullopt;
    t.step_angle_rad = stepAngleOfSeenEdges(phi, seen);
    if (t.step_angle_rad < p.min_step_angle_deg * M_PI / 180.0) return std::nullopt;
    t.inner_radius_m = lowerMedian(inner);  // hidden inner parts only read long
    t.outer_radius_m = quantile(outer, 0.5);
    t.run_m = runAtMidRadius(t, t.inner_radius_m);
    return t;
}

double runAtMidRadius(const TurningFlight& t, double inner_radius_m) {
    return (inner_radius_m + t.outer_radius_m) * std::sin(0.5 * t.step_angle_rad);
}

}  // namespace stairmap
