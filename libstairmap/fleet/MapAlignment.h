#pragma once
// Estimating the 4-DoF transform between two landmark maps from the staircases they share
// (issue 13, item 1). Robust to wrong pairings: every pair of staircases whose shapes agree
// (rise, run, width, turn per step) proposes one transform per whole-step shift along the flight
// (fleet/StaircasePairing.h); each proposal is scored by how many staircases of the two maps it
// lays on top of each other (a landmark counts when >= min_overlap_steps of its nosings coincide
// and no end either map saw is contradicted), refined by least squares over all coinciding
// nosings (fleet/AlignmentFit.h) and scored again. The proposals are enumerated exhaustively
// (RANSAC with every minimal sample: maps hold tens of staircases, not thousands).
//
// Ambiguity rule (docs/merge.md): the best transform is accepted only if no other, different
// transform (params.distinct_*) explains as many shared staircases. A flight seen partially by
// both maps with no common end, or a map that sees one of two identical flights, is refused.

#include <string>
#include <vector>

#include "fleet/AlignmentFit.h"
#include "fleet/AlignmentParams.h"
#include "fleet/Transform4.h"
#include "map/LandmarkTypes.h"

namespace stairmap::fleet {

enum class AlignmentStatus {
    Aligned,            ///< one transform explains the shared staircases
    NoSharedStaircase,  ///< no staircase pair agrees in shape and overlaps
    Ambiguous           ///< several different transforms explain equally many staircases
};

/// Landmark IDs of one staircase in the first map and in the other map.
struct LandmarkPair {
    int first_id = -1;
    int other_id = -1;
};

struct AlignmentResult {
    AlignmentStatus status = AlignmentStatus::NoSharedStaircase;
    Transform4 T_first_other;              ///< p_first = T_first_other * p_other (when Aligned)
    AlignmentSigma sigma;
    std::vector<LandmarkPair> pairs;       ///< staircases the transform lays on each other
    int matched_steps = 0;                 ///< nosing pairs of the final least-squares fit
    double rms_perp_m = 0.0;               ///< [m] their rms distance across the nosing lines
    std::vector<Transform4> alternatives;  ///< the competing transforms (when Ambiguous)
    std::string reason;                    ///< why not Aligned, one sentence
};

/// Aligns `other` to `first` (both canonical landmark maps, each in its own frame).
/// Cost O(P S L^2 k^2): P shape-compatible pairs, S shifts each, L landmarks, k steps.
AlignmentResult estimateAlignment(const LandmarkMapState& first, const LandmarkMapState& other,
                                  const AlignmentParams& params = {});

/// The shared staircases and nosing fit of a GIVEN transform (for `--align`): status Aligned
/// when at least one staircase coincides, else NoSharedStaircase with the given transform kept.
AlignmentResult evaluateAlignment(const LandmarkMapState& first, const LandmarkMapState& other,
                                  const Transform4& T_first_other,
                                  const AlignmentParams& params = {});

}  // namespace stairmap::fleet
