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

/// Second views of one flight that Algorithm 2 (OverlappingFlights.h) leaves apart: two chains
/// through a flight's scattered nosings whose levels differ (a depth camera's chains of 0.19 and
/// 0.17 m rises on one 0.177 m flight, dev3 r0042), so no edge of one is the same stair as an edge
/// of the other. Seen from above they cover the same ground along the same heading.
struct SecondViewParams {
    double max_heading_diff_deg = 20.0;  ///< [deg] the two headings agree within this
    double min_on_fraction = 0.5;  ///< [-] of the shorter flight's edges on the longer's footprint
    FlightFootprintParams footprint{0.30, 0.0};  ///< the footprint's box only (straight flights)
};

/// Of two same-direction flights in `flights` with headings within max_heading_diff_deg, drops the
/// one with fewer steps (the later one on a tie) when at least min_on_fraction of its edge centres
/// lie on the other's footprint. Flights side by side (beyond the lateral margin), one beyond the
/// other along the heading, and a flight above another with the opposite heading (a switchback)
/// are kept. Returns how many were dropped. O(n^2 k^2) for n flights of k steps.
int dropSecondViews(std::vector<Staircase>& flights, const SecondViewParams& params = {});

}  // namespace stairmap
