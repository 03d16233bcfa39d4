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
    int radial = 0;
    for (const StairEdge& e : s.steps) {
        const Eigen::Vector2d p0 = e.start.head<2>() - t.axis, p1 = e.end.head<2>() - t.axis;
        const Eigen::Vector2d d = (p1 - p0).normalized();
        radial += std::abs(d.x() * p0.y() - d.y() * p0.x()) <= p.max_axis_offset_m;
        const Eigen::Vector2d far = p0.norm() > p1.norm() ? p0 : p1;
        double angle = std::atan2(far.y(), far.x());
        if (!phi.empty()) angle = phi.back() + std::remainder(angle - phi.back(), 2.0 * M_PI);
        phi.push_back(angle);
        if (e.num_points > 0) {  // seen; put-back edges are interpolated
            inner.push_back(std::min(p0.norm(), p1.norm()));
            outer.push_back(std::max(p0.norm(), p1.norm()));
        }
    }
    if (2 * radial <= static_cast<int>(n) || inner.empty()) return std::nullopt;
    // Theil-Sen over the seen edges: a level whose line lies off its nosing's angle (a back edge
    // one step ahead, a short line at the column) turns a least-squares slope (dev r0144, its top
    // level of four a back edge: 23.1 deg read for 17.5, now 19.4); put-back edges only repeat the
    // helix they were interpolated on.
    t.step_angle_rad = std::abs(medianPairwiseSlope(phi, seenEdges(s.steps), 1));
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
