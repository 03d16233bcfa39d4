#pragma once
// Linking a staircase to the floors it connects from the robot's own climbs (issue 4, item 4
// "Floors"). The detector rarely sees a whole flight, so the highest seen nosing often lies far
// below the upper floor; but when the robot itself walks up (or down) through the flight from
// one floor level to another, that climb names both floors.

#include <optional>

#include "map/LandmarkParams.h"
#include "map/LandmarkTypes.h"

namespace stairmap {

/// Heights [m] of the two floors a transit connects, low first.
struct TraversedFloors {
    double low_z = 0.0;
    double high_z = 0.0;
};

/// The floors `transit` connects if it went through `canonical` (a canonical, world-frame flight),
/// nullopt otherwise. Rule (see docs/landmarks.md, "Floors"):
/// - the transit's ends are floor heights more than floor_merge_tolerance_m apart, and their
///   difference is at most max_flight_rise_m above the flight's bottom floor;
/// - the flight's seen nosings lie between the two floors (within traversal_margin_m);
/// - at least traversal_min_fraction of the samples taken while climbing (not the two ends) lie in
///   the flight's corridor: laterally within half the width plus the margin, along the uphill
///   heading from one run before the lowest nosing to where the flight, extended by whole rises,
///   reaches the upper floor (plus the margin), and at the height the flight has there (within
///   traversal_height_tolerance_m);
/// - the climb moves uphill along the heading when it rises (downhill when it descends).
std::optional<TraversedFloors> traversedFloors(const Staircase& canonical,
                                               const FloorTransit& transit,
                                               const LandmarkParams& params);

}  // namespace stairmap
