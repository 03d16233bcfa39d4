#pragma once
// Fusing landmark maps, already aligned, into the first map's frame (issue 13, item 1): each
// staircase of a later map is moved by T_first_this, associated with the fused map's staircases
// by the landmark map's own test (map/StaircaseAssociation.h: sameStaircase) and merged by the
// core's Algorithm 2 (core/StaircaseMerge.h: mergeCanonical, observation-weighted); unmatched ones
// become new landmarks with new IDs, so the first map's IDs stay. Floor levels and robot climbs
// are moved too; LandmarkMap then re-derives confirmation and merges floors closer than
// floor_merge_tolerance_m. Provenance is kept per landmark and per step.

#include <vector>

#include "fleet/Transform4.h"
#include "map/LandmarkParams.h"
#include "map/LandmarkTypes.h"

namespace stairmap::fleet {

/// Who contributed: map index (0 = first, in the order given) and how often it saw it.
struct Contribution {
    int map = 0;
    int source_id = -1;    ///< landmark id in that map (-1 in per-step entries: summed per map)
    int observations = 0;  ///< detections of that map fused into the landmark (or the step)
};

struct LandmarkProvenance {
    int id = -1;                                   ///< landmark id in the fused map
    std::vector<Contribution> sources;             ///< one per contributing source landmark
    std::vector<std::vector<Contribution>> steps;  ///< per fused step (bottom to top), per map
};

class MapFusion {
public:
    /// Starts from the first map (map 0). Throws std::invalid_argument for an inconsistent state.
    MapFusion(LandmarkMapState first, const LandmarkParams& params);

    /// Adds the next map, moved into the first map's frame by T_first_this. Returns the index
    /// given to it. Cost O(L_this x L_fused x k^2).
    int add(const LandmarkMapState& other, const Transform4& T_first_this);

    /// The fused map so far (first map's frame; confirmation and floors re-derived).
    const LandmarkMapState& state() const { return state_; }
    const LandmarkParams& params() const { return params_; }
    /// Per landmark of state(), ordered by id.
    std::vector<LandmarkProvenance> provenance() const;

private:
    /// A source landmark moved into the first map's frame, remembered for per-step provenance.
    struct Source {
        int map = 0;
        int source_id = -1;
        int observations = 0;
        Staircase stairs;
        std::vector<int> step_observations;
    };

    void addLandmark(const StaircaseLandmark& moved, const Source& source);
    void addFloors(const LandmarkMapState& other, const Transform4& T);
    void refresh();
    std::vector<std::vector<Contribution>> stepProvenance(const StaircaseLandmark& lm,
                                                          const std::vector<Source>& srcs) const;

    LandmarkParams params_;
    LandmarkMapState state_;
    int maps_ = 1;
    std::vector<std::pair<int, Source>> sources_;  ///< fused landmark id -> source
};

}  // namespace stairmap::fleet
