#pragma once
// Fusing two canonical observations of the same flight (paper Algorithm 2): corresponding steps
// are fused with fuseEdges, steps only one side saw are added, geometry re-estimated.

#include <vector>

#include "core/Staircase.h"
#include "map/LandmarkParams.h"

namespace stairmap {

/// A canonical staircase with per-step observation counts (weights for the end points).
struct WeightedStaircase {
    Staircase stairs;
    std::vector<int> step_observations;  ///< same size as stairs.steps
};

/// Fuses b into a (both canonical, already associated). Steps correspond by level: b's step
/// heights, corrected by the median height offset of the step pairs that match by Definition 2
/// (0 if none), are paired one-to-one with a's nearest step within half a rise. Paired steps are
/// fused, the others added; steps neither saw (a gap between two partial views) are not invented.
/// The result is canonical, sorted bottom to top, with re-estimated geometry.
WeightedStaircase fuseStaircases(const WeightedStaircase& a, const WeightedStaircase& b,
                                 const LandmarkParams& params);

}  // namespace stairmap
