#pragma once
// Staircase footprints drawn into a floor's grid (same origin, resolution and size), so that a
// planner can keep out of them or hand them to a stair behaviour.

#include <array>
#include <vector>

#include "export/FlightGeometry.h"
#include "export/FloorGrid.h"

namespace stairmap::exporting {

/// Corners (world xy) of a flight's footprint: from the foot of the first riser to the top
/// nosing, across its width; counter-clockwise from the bottom right.
std::array<Eigen::Vector2d, 4> flightFootprint(const FlightGeometry& flight);

/// A grid shaped like `floor` with Occupied where a cell centre lies in one of the footprints
/// and Free elsewhere. Cost: O(cells x flights).
FloorGrid stairMask(const FloorGrid& floor, const std::vector<FlightGeometry>& flights);

}  // namespace stairmap::exporting
