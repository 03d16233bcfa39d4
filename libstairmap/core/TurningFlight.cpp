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

/// Least-squares slope of `values` against `levels`.
double slopeAgainst(const std::vector<double>& levels, const std::vector<double>& values) {
    const double n = static_cast<double>(levels.size());
    double sl = 0, sv = 0, sll = 0, slv = 0;
    for (std::size_t k = 0; k < levels.size(); ++k) {
        sl += levels[k];
        sv += values[k];
        sll += levels[k] * levels[k];
        slv += levels[k] * values[k];
    }
    return (n * slv - sl * sv) / (n * sll - sl * sl);
}

/// Whole number of steps (1 to 3) a turn is of `step`, within `tolerance` of it; 0 if none.
int stepsInTurn(double turn, double step, double tolerance) {
    const double m = std::round(turn / step);
    return m >= 1 && m <= 3 && std::abs(turn / step - m) <= tolerance ? static_cast<int>(m) : 0;
}

/// Levels of the edges from their turns `turns` (> 0 when turning the flight's way): a chain's
/// edges are consecutive nosings except where one was stepped over (a far ring missed it), a turn
/// of two or three steps. The step is the seen turn that the most turns are whole multiples of
/// (the largest on a tie); a turn of two or three of it counts that many levels, any other one.
/// Empty when no turn explains two.
std::vector<double> levelsOfTurns(const std::vector<double>& turns, double min_step,
                                  double tolerance) {
    double step = 0.0;
    int best = 0;
    for (double candidate : turns) {
        if (candidate < min_step) continue;
        int count = 0;
        for (double turn : turns) count += stepsInTurn(turn, candidate, tolerance) > 0;
        if (count > best || (count == best && candidate > step)) {
            best = count;
            step = candidate;
        }
    }
    if (best < 2) return {};
    std::vector<double> levels{0.0};
    for (double turn : turns)
        levels.push_back(levels.back() + std::max(1, stepsInTurn(turn, step, tolerance)));
    return levels;
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
    t.step_angle_rad = std::abs(slopeAgainstIndex(phi));
    const double min_step = p.min_step_angle_deg * M_PI / 180.0;
    if (t.step_angle_rad < min_step) return std::nullopt;
    // Against the edges' levels rather than their index when some turns are whole steps stepped
    // over (dev3 r0068: turns 31, 59, 59, 31, 37 deg, 45.6 -> 30.6 deg for 30.3).
    const double way = phi.back() > phi.front() ? 1.0 : -1.0;
    std::vector<double> turns;
    for (std::size_t k = 1; k < n; ++k) turns.push_back(way * (phi[k] - phi[k - 1]));
    const std::vector<double> levels = levelsOfTurns(turns, min_step, p.turn_tolerance);
    if (!levels.empty() && levels.back() > static_cast<double>(n - 1))
        t.step_angle_rad = std::abs(slopeAgainst(levels, phi));
    t.inner_radius_m = quantile(inner, 0.5);
    t.outer_radius_m = quantile(outer, 0.5);
    t.run_m = (t.inner_radius_m + t.outer_radius_m) * std::sin(0.5 * t.step_angle_rad);
    return t;
}

}  // namespace stairmap
