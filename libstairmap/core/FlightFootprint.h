#pragma once
// The ground a found flight covers, for passes that look again for flights the first pass missed
// (StairDetector's tilted-ring pass): their lines and flights on a flight already found are that
// flight seen again, not another one.
// Footprint: along the flight's heading from one run before its first edge to one run past its
// last, sideways over its edges' ends plus a margin; and, for a turning flight whose heading box
// fits its steps poorly, a radius around every edge. Height is not compared: in one view, a
// flight stacked right above another is not a case the second pass is for.

#include <Eigen/Core>
#include <vector>

#include "core/Staircase.h"

namespace stairmap {

struct FlightFootprintParams {
    double lateral_margin_m = 0.30;  ///< [m] beyond the edges' ends, sideways (an unseen side)
    double edge_radius_m = 0.30;     ///< [m] around each edge (XY distance to the segment)
};

/// Whether the XY point `p` lies on `flight`'s footprint.
bool onFlightFootprint(const Eigen::Vector2d& p, const Staircase& flight,
                       const FlightFootprintParams& params = {});

/// Whether `p` lies on the footprint of any of `flights`.
bool onAnyFlightFootprint(const Eigen::Vector2d& p, const std::vector<Staircase>& flights,
                          const FlightFootprintParams& params = {});

/// Whether any edge of `flight` lies (by its centre) on the footprint of one of `others`.
bool overlapsAnyFlight(const Staircase& flight, const std::vector<Staircase>& others,
                       const FlightFootprintParams& params = {});

}  // namespace stairmap
