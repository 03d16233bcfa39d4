#include "core/FlightJoin.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/StaircaseGeometry.h"

namespace stairmap {
namespace {

/// Union of the lateral extents of a flight's edges [m].
std::pair<double, double> flightExtent(const Staircase& s, const Eigen::Vector2d& lateral) {
    std::pair<double, double> ext{std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity()};
    for (const StairEdge& e : s.steps) {
        const auto x = lateralExtent(e, lateral);
        ext = {std::min(ext.first, x.first), std::max(ext.second, x.second)};
    }
    return ext;
}

/// True when `far` starts beyond `near`'s last edge as a continuation of the same flight.
bool continues(const Staircase& near, const Staircase& far, const FlightJoinParams& p) {
    if (near.direction != far.direction || near.steps.empty() || far.steps.empty()) return false;
    const double turn = std::abs(std::remainder(far.heading_rad - near.heading_rad, 2 * M_PI));
    if (turn > p.max_heading_diff_deg * M_PI / 180.0) return false;
    const Eigen::Vector2d h(std::cos(near.heading_rad), std::sin(near.heading_rad));
    const StairEdge& last = near.steps.back();
    const StairEdge& first = far.steps.front();
    const double gap = h.dot((first.centre() - last.centre()).head<2>());
    if (gap <= 0.0 || gap > p.max_gap_runs * near.step_depth) return false;
    const double up = near.direction == StairDirection::Ascending ? 1.0 : -1.0;
    const double climb = up * (first.centre().z() - last.centre().z());
    if (climb < -p.height_tolerance_m ||
        climb > p.max_gap_runs * near.step_height + p.height_tolerance_m)
        return false;
    // Over the same width: the flights' whole lateral extents, as a facing edge may be a piece.
    const Eigen::Vector2d lateral(-h.y(), h.x());
    const auto a = flightExtent(near, lateral), b = flightExtent(far, lateral);
    const double common = std::min(a.second, b.second) - std::max(a.first, b.first);
    return common >= p.min_lateral_overlap * std::min(a.second - a.first, b.second - b.first);
}

/// True when far's edges are near's next steps: one run apart each and on its nosing line.
bool onNosingLine(const Staircase& near, const Staircase& far, const FlightJoinParams& p) {
    const Eigen::Vector2d h(std::cos(near.heading_rad), std::sin(near.heading_rad));
    const double up = near.direction == StairDirection::Ascending ? 1.0 : -1.0;
    const Eigen::Vector3d base = near.steps.back().centre();
    for (std::size_t k = 0; k < far.steps.size(); ++k) {
        const Eigen::Vector3d c = far.steps[k].centre();
        const double n = static_cast<double>(k + 1);  // steps beyond near's last edge
        if (std::abs(h.dot((c - base).head<2>()) - n * near.step_depth) > 0.5 * near.step_depth)
            return false;
        if (std::abs(up * (c.z() - base.z()) - n * near.step_height) > p.height_tolerance_m)
            return false;
    }
    return true;
}

}  // namespace

int joinContinuedFlights(std::vector<Staircase>& found, const FlightJoinParams& params) {
    int removed = 0;
    for (std::size_t i = 0; i < found.size(); ++i) {
        for (std::size_t j = 0; j < found.size(); ++j) {
            if (i == j || !continues(found[i], found[j], params)) continue;
            if (onNosingLine(found[i], found[j], params)) {
                found[i].steps.insert(found[i].steps.end(), found[j].steps.begin(),
                                      found[j].steps.end());
                estimateGeometry(found[i]);
            }
            found.erase(found.begin() + static_cast<std::ptrdiff_t>(j));
            ++removed;
            return removed + joinContinuedFlights(found, params);  // indices moved: start over
        }
    }
    return removed;
}

}  // namespace stairmap
