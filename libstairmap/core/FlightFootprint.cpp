#include "core/FlightFootprint.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stairmap {
namespace {

/// XY distance from `p` to the segment of `e`.
double distanceToEdge(const Eigen::Vector2d& p, const StairEdge& e) {
    const Eigen::Vector2d a = e.start.head<2>();
    const Eigen::Vector2d d = e.end.head<2>() - a;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + t * d)).norm();
}

}  // namespace

bool onFlightFootprint(const Eigen::Vector2d& p, const Staircase& flight,
                       const FlightFootprintParams& params) {
    if (flight.steps.empty()) return false;
    for (const StairEdge& e : flight.steps)
        if (distanceToEdge(p, e) < params.edge_radius_m) return true;
    const Eigen::Vector2d origin = flight.steps.front().centre().head<2>();
    const Eigen::Vector2d along(std::cos(flight.heading_rad), std::sin(flight.heading_rad));
    const Eigen::Vector2d left(-along.y(), along.x());
    double last = 0.0;
    double side_lo = std::numeric_limits<double>::infinity();
    double side_hi = -side_lo;
    for (const StairEdge& e : flight.steps) {
        last = std::max(last, (e.centre().head<2>() - origin).dot(along));
        for (const Eigen::Vector3d& end : {e.start, e.end}) {
            const double side = (end.head<2>() - origin).dot(left);
            side_lo = std::min(side_lo, side);
            side_hi = std::max(side_hi, side);
        }
    }
    const Eigen::Vector2d q = p - origin;
    const double a = q.dot(along), s = q.dot(left);
    return a > -flight.step_depth && a < last + flight.step_depth &&
           s > side_lo - params.lateral_margin_m && s < side_hi + params.lateral_margin_m;
}

bool onAnyFlightFootprint(const Eigen::Vector2d& p, const std::vector<Staircase>& flights,
                          const FlightFootprintParams& params) {
    return std::any_of(flights.begin(), flights.end(),
                       [&](const Staircase& f) { return onFlightFootprint(p, f, params); });
}

bool overlapsAnyFlight(const Staircase& flight, const std::vector<Staircase>& others,
                       const FlightFootprintParams& params) {
    return std::any_of(flight.steps.begin(), flight.steps.end(), [&](const StairEdge& e) {
        return onAnyFlightFootprint(e.centre().head<2>(), others, params);
    });
}

int dropSecondViews(std::vector<Staircase>& flights, const SecondViewParams& params) {
    const double max_heading = params.max_heading_diff_deg * M_PI / 180.0;
    std::vector<char> dropped(flights.size(), 0);
    // Whether `a` is the stronger of the two: more steps, or as many and listed first.
    const auto stronger = [&](std::size_t a, std::size_t b) {
        return flights[a].steps.size() > flights[b].steps.size() ||
               (flights[a].steps.size() == flights[b].steps.size() && a < b);
    };
    for (std::size_t i = 0; i < flights.size(); ++i)
        for (std::size_t j = 0; j < flights.size(); ++j) {
            if (i == j || dropped[i] || dropped[j] || !stronger(i, j)) continue;
            const Staircase& keep = flights[i];
            const Staircase& weak = flights[j];
            if (keep.direction != weak.direction || weak.steps.empty()) continue;
            const double turn = std::remainder(keep.heading_rad - weak.heading_rad, 2.0 * M_PI);
            if (std::abs(turn) > max_heading) continue;
            const auto on =
                std::count_if(weak.steps.begin(), weak.steps.end(), [&](const StairEdge& e) {
                    return onFlightFootprint(e.centre().head<2>(), keep, params.footprint);
                });
            if (static_cast<double>(on) >=
                params.min_on_fraction * static_cast<double>(weak.steps.size()))
                dropped[j] = 1;
        }
    std::size_t out = 0;
    for (std::size_t i = 0; i < flights.size(); ++i) {
        if (dropped[i]) continue;
        if (out != i) flights[out] = std::move(flights[i]);
        ++out;
    }
    const int removed = static_cast<int>(flights.size() - out);
    flights.resize(out);
    return removed;
}

}  // namespace stairmap
