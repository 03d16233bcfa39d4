#pragma once
// Canonical staircase form, whichever end a flight was seen from, and its geometry computed from
// the step edges. The landmark map stores flights in it; core/StaircaseMerge merges in it.

#include <optional>

#include "core/Staircase.h"

namespace stairmap {

/// Canonical form of a staircase seen from either end: direction Ascending, steps sorted bottom to
/// top by height, heading = uphill, each edge's start on the left and end on the right when
/// facing uphill (the convention of core/Staircase.h), geometry re-estimated (see
/// updateCanonicalGeometry). Returns nullopt for a staircase with no steps or non-finite coordinates.
std::optional<Staircase> canonicalStaircase(const Staircase& staircase);

/// Re-estimates the geometry of a canonical staircase from its edges (paper Sec. III-C):
/// heading from the length-weighted mean edge direction, oriented from the lowest to the highest
/// edge; step_height / step_depth = least-squares slopes of edge height / position along the
/// heading against the step level (levels from the heights, so unseen steps in between are
/// allowed); step_width = median edge length; slope = atan(h / d);
/// location = centre of the lowest edge. With a single step, height/depth/heading are kept.
/// Also orients every edge start-left / end-right.
void updateCanonicalGeometry(Staircase& staircase);

/// Unit uphill direction in the xy plane.
Eigen::Vector2d headingVector(const Staircase& staircase);

}  // namespace stairmap
