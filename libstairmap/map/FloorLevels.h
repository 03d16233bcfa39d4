#pragma once
// Floor levels: height clusters of where the robot drove and of staircase ends (issue 4, item 4).
// A floor is reported once enough robot samples fell on it (samples taken while climbing stay
// below the threshold) or a confirmed staircase's observed bottom or top lies on it.

#include <vector>

#include "map/LandmarkParams.h"
#include "map/LandmarkTypes.h"

namespace stairmap {

/// Height of the lowest tread's floor (lowest edge minus one rise) and of the top floor (the
/// highest edge: the last nosing is flush with the upper floor).
double staircaseBottomZ(const Staircase& canonical);
double staircaseTopZ(const Staircase& canonical);

bool isReportedFloor(const Floor& floor, const LandmarkParams& params);

/// Adds one robot floor height to the nearest level within tolerance, or starts a new level.
void addRobotFloorSample(LandmarkMapState& state, double z, const LandmarkParams& params);

/// Recomputes every level's staircase ends from the confirmed landmarks' observed ends (creating
/// levels for ends
/// that fall on none and dropping levels left without support), merges levels closer than the
/// tolerance (keeping the lower id), and sets each landmark's bottom_floor/top_floor: from the
/// latest robot transit that went through it (map/StaircaseTraversal.h) when there is one, else
/// the nearest reported level within tolerance of its bottom/top (-1 if none).
void refreshFloorLevels(LandmarkMapState& state, const LandmarkParams& params);

}  // namespace stairmap
