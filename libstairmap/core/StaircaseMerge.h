#pragma once
// Merging two detections of the same staircase (paper Sec. III-E, Algorithm 2 with Definition 2):
// the one implementation, used by the detector (two chains of one split flight) and by the
// landmark map (a detection into a landmark, two landmarks into one).
//
// Deviations from the paper, and why (docs/detector.md, docs/landmarks.md):
//  - Correspondence: the anchor pair (lines 2-9) only decides match / NO_MATCH; steps then pair by
//    LEVEL (nearest height within half a rise, one to one), not by index from the anchor (l_i+1
//    with l_j+1): a detector that missed one nosing shifts every later index, its heights do not
//    move. With no missing step this is Algorithm 2's pairing. (A height offset taken from the
//    anchor would change nothing: Definition 2 bounds it by 5 cm, below half of any rise >= 11 cm.)
//  - merge(l_i, l_j) is covariance-weighted (information form); ends closer than a tolerance are
//    averaged, farther ones extend the edge (see StairEdgeFusion.h).
//  - Adjacent steps that end up the same stair are fused (no doubled step after a doubtful pair).
//  - StepAnchor::AssociatedElsewhere merges without a common step, for callers that associated the
//    two flights by other evidence (the landmark map's footprint overlap or flight continuation);
//    steps then pair by absolute height. Algorithm 2 proper returns NO_MATCH there.

#include <optional>
#include <vector>

#include "core/MergeParams.h"
#include "core/Staircase.h"
#include "core/StairEdgeFusion.h"

namespace stairmap {

/// A staircase with per-step observation counts (the weights of the end points when fusing).
struct WeightedStaircase {
    Staircase stairs;
    std::vector<int> step_observations;  ///< same size as stairs.steps, each >= 1
};

/// What merging requires before it fuses.
enum class StepAnchor {
    Required,            ///< Algorithm 2: at least one Definition-2 pair, else NO_MATCH
    AssociatedElsewhere  ///< the caller knows they are one flight: merge even without a pair
};

/// Algorithm 2, lines 2-9: some edge of a and some edge of b are the same stair (Definition 2).
/// Cost O(k m).
bool haveCommonStair(const Staircase& a, const Staircase& b, const MergeParams& params = {});

/// Algorithm 2 on two detections in the same frame with the same `direction` and ordering
/// (steps outward from the observer's floor, as the detector makes them; for a flight seen from
/// both ends, canonicalise both first with canonicalStaircase()). Steps are paired as described
/// above, paired ones fused, unpaired ones kept, the result ordered outward and its geometry
/// re-estimated with estimateGeometry (Sec. III-D). Returns std::nullopt (NO_MATCH) when no edge
/// pair is the same stair. Throws std::invalid_argument if the directions differ or params are
/// invalid. Cost O(k m) for k and m steps.
std::optional<Staircase> mergeStaircases(const Staircase& a, const Staircase& b,
                                         const MergeParams& params = {});

/// The same merge on weighted staircases in canonical form (core/StaircaseCanonical.h: Ascending,
/// bottom to top): observation counts weight the end points and add up per step; the geometry
/// is re-estimated with updateCanonicalGeometry (rise/run fitted against levels, so steps nobody
/// saw between two partial views are allowed and never invented). Returns std::nullopt only for
/// StepAnchor::Required without a Definition-2 pair. Throws std::invalid_argument if an input is
/// not Ascending, its counts do not match its steps, or params are invalid.
std::optional<WeightedStaircase> mergeCanonical(const WeightedStaircase& a,
                                                const WeightedStaircase& b,
                                                const MergeParams& params,
                                                StepAnchor anchor = StepAnchor::Required);

}  // namespace stairmap
