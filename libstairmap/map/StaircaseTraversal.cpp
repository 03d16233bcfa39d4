#include "map/StaircaseTraversal.h"

#include <algorithm>
#include <cmath>

#include "core/StaircaseCanonical.h"
#include "map/FloorLevels.h"

namespace stairmap {
namespace {

constexpr double kDefaultRun = 0.25;  // [m] for a single-step flight without a run estimate
/// [m] samples this far onto the floor beyond either end of the flight still count (at the
/// floor's height): the level guard needs some level path before it reports level ground.
constexpr double kFloorApronM = 1.0;

/// Where a sample lies relative to the flight: along the uphill heading from the lowest nosing,
/// across it (left positive), both [m].
struct FlightCoords {
    double along = 0.0;
    double across = 0.0;
};

FlightCoords flightCoords(const Staircase& s, const Eigen::Vector3d& p) {
    const Eigen::Vector2d u = headingVector(s);
    const Eigen::Vector2d d = (p - s.steps.front().centre()).head<2>();
    return {d.dot(u), u.x() * d.y() - u.y() * d.x()};
}

/// The sample stands on the flight, extended by whole steps down to the lower floor and up to
/// the upper one (a partial view), at the flight's height there.
bool onFlight(const Staircase& s, const Eigen::Vector3d& p, const TraversedFloors& floors,
              const LandmarkParams& params) {
    const double rise = s.step_height, run = s.step_depth > 0.0 ? s.step_depth : kDefaultRun;
    const double margin = params.traversal_margin_m;
    const double bottom_z = staircaseBottomZ(s);
    // Step levels (bottom_z + level * rise) of the two floors; tread k (0-based from the lowest
    // seen nosing) is at level k + 1, so the floor below it ends at along = (level - 1) * run.
    const double low_level = (floors.low_z - bottom_z) / rise;
    const double high_level = (floors.high_z - bottom_z) / rise;
    const FlightCoords c = flightCoords(s, p);
    if (std::abs(c.across) > 0.5 * s.step_width + margin) return false;
    const double apron = margin + kFloorApronM;
    if (c.along < (low_level - 1.0) * run - apron || c.along > high_level * run + apron)
        return false;
    const double level = std::clamp(std::floor(c.along / run) + 1.0, low_level, high_level);
    return std::abs(p.z() - (bottom_z + level * rise)) <= params.traversal_height_tolerance_m;
}

}  // namespace

std::optional<TraversedFloors> traversedFloors(const Staircase& s, const FloorTransit& transit,
                                               const LandmarkParams& params) {
    const std::vector<Eigen::Vector3d>& path = transit.floor_path;
    if (s.steps.empty() || !(s.step_height > 0.0) || path.size() < 3) return std::nullopt;
    const Eigen::Vector3d& first = path.front();
    const Eigen::Vector3d& last = path.back();
    const TraversedFloors floors{std::min(first.z(), last.z()), std::max(first.z(), last.z())};
    const double tol = params.floor_merge_tolerance_m;
    if (floors.high_z - floors.low_z <= tol) return std::nullopt;
    const double margin = params.traversal_margin_m;
    if (staircaseBottomZ(s) < floors.low_z - margin || staircaseTopZ(s) > floors.high_z + margin)
        return std::nullopt;
    if (floors.high_z - floors.low_z > params.max_flight_rise_m) return std::nullopt;
    // Climbing moves uphill, descending downhill.
    const double progress = (last - first).head<2>().dot(headingVector(s));
    if (progress * (last.z() - first.z()) <= 0.0) return std::nullopt;
    int inside = 0;
    for (std::size_t i = 1; i + 1 < path.size(); ++i) {
        if (onFlight(s, path[i], floors, params)) ++inside;
    }
    const double fraction = static_cast<double>(inside) / static_cast<double>(path.size() - 2);
    if (inside == 0 || fraction < params.traversal_min_fraction) return std::nullopt;
    return floors;
}

}  // namespace stairmap
