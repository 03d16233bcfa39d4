#pragma once
// Fusing two canonical observations of the same flight (paper Algorithm 2): corresponding steps
// are fused with fuseEdges, steps only one side saw are prepended/appended, geometry re-estimated.

#include <vector>

#include "core/Staircase.h"
#include "map/LandmarkParams.h"

namespace stairmap {

/// A canonical staircase with per-step observation counts (weights for the end points).
struct WeightedStaircase {
    Staircase stairs;
    std::vector<int> step_observations;  ///< same size as stairs.steps
};

/// Fuses b into a, where b.steps[i] corresponds to a.steps[i + offset] (see stepOffset). Steps
/// that would leave a gap between the two flights are not invented: the flights are joined end
/// to end instead. The result is canonical with re-estimated geometry.
WeightedStaircase fuseStaircases(const WeightedStaircase& a, const WeightedStaircase& b,
                                 int offset, const LandmarkParams& params);

}  // namespace stairmap
