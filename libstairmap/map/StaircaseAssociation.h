#pragma once
// Deciding whether two canonical world-frame staircases are the same flight, and how their steps
// line up. Inputs must be canonical (core/StaircaseCanonical.h). Step pairs use the core
// Definition 2 (core/StairEdgeFusion.h: isSameStairEdge with toMergeParams(params)).

#include <vector>

#include "core/Staircase.h"
#include "map/LandmarkParams.h"

namespace stairmap {

/// Uphill headings agree within params.heading_tolerance_deg.
bool headingsAgree(const Staircase& a, const Staircase& b, const LandmarkParams& params);

/// xy footprints (first to last edge, widened by half a run) overlap by at least
/// params.footprint_min_overlap of the smaller one, and the height ranges
/// [lowest edge - rise, highest edge] overlap by params.footprint_min_z_overlap_m.
bool footprintsOverlap(const Staircase& a, const Staircase& b, const LandmarkParams& params);

/// Headings agree and (some step pair is the same stair: core haveCommonStair, Algorithm 2's
/// match test; or footprints overlap when enabled; or
/// one continues the other along the flight, see LandmarkParams::max_extrapolated_steps).
bool sameStaircase(const Staircase& a, const Staircase& b, const LandmarkParams& params);

}  // namespace stairmap
